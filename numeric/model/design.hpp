// The design of a program under a model: the design matrix H (one row h(eta_i) per position) and
// the information matrix H^T H, accumulated without forming H. The model defaults to the paper's.
#pragma once
#include "numeric/model/paper9.hpp"

namespace scalcal {

template <class Model = Paper9Model, class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Model::kParameters> design_matrix(const PositionsT<Scalar>& positions) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Model::kParameters> H(static_cast<Eigen::Index>(positions.size()),
                                                              Model::kParameters);
  for (std::size_t i = 0; i < positions.size(); ++i)
    H.row(static_cast<Eigen::Index>(i)) = Model::row(positions[i]).transpose();
  return H;
}

// H^T H = sum_i h_i h_i^T, symmetric by construction (the lower triangle is mirrored).
template <class Model = Paper9Model, class Scalar>
InformationT<Model, Scalar> information_matrix(const PositionsT<Scalar>& positions) {
  InformationT<Model, Scalar> M = InformationT<Model, Scalar>::Zero();
  for (const auto& eta : positions) {
    const RowT<Model, Scalar> h = Model::row(eta);
    M.template selfadjointView<Eigen::Lower>().rankUpdate(h);
  }
  M.template triangularView<Eigen::StrictlyUpper>() = M.transpose();
  return M;
}

}  // namespace scalcal
