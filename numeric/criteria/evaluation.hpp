// Evaluation of a program as the paper compares programs: K = (H^T H)^-1 and the D, A, E and
// max-diagonal criteria, normalised by N (D by N^9), and the RMS errors theta_q (eq. 7). A
// program whose H is rank-deficient is reported with its rank and the parameters it cannot
// identify; criteria are then +infinity, never a regularised number.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/SVD>

#include "numeric/model/design.hpp"
#include "numeric/model/parameters.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

template <class Scalar>
struct EvaluationTpl {
  int positions = 0;
  int rank = 0;
  Scalar condition;  // 2-norm condition number of H^T H: lambda_max / lambda_min
  // Normalised criteria: D = N^9 det K, A = N trace K, E = N lambda_max(K), S = N max_r K(r,r).
  Scalar D, A, E, S;
  // theta_q = sqrt(N max K(r,r)) over the three parameters of each group (eq. 7, times sqrt N).
  Scalar theta_bias, theta_scale, theta_nonorth;
  // The same criteria without normalisation.
  Scalar det_K, trace_K, lambda_max_K, max_diag_K;
  Mat9T<Scalar> information;      // H^T H
  Mat9T<Scalar> K;                // (H^T H)^-1, zero when rank < 9
  std::vector<int> unidentifiable;  // indices into kParameterNames, empty when rank == 9

  bool full_rank() const { return rank == kParameters; }
};

using Evaluation = EvaluationTpl<double>;

namespace detail {

// Everything comes from the SVD of H, not from an eigen-decomposition of H^T H: squaring H
// squares its condition number, and a nearly singular program would otherwise get a tiny or even
// negative eigenvalue (and so a negative det K or lambda_max K). With H = U diag(sigma) V^T,
// K = V diag(sigma^-2) V^T exactly. The rank uses the usual tolerance max(N, 9) eps sigma_max;
// a parameter whose unit vector has a component in the null space is not identifiable.
template <class Scalar>
Vec9T<Scalar> singular_values(const std::vector<Vec3T<Scalar>>& positions, EvaluationTpl<Scalar>& ev,
                              Mat9T<Scalar>& V) {
  using std::sqrt;
  const DesignMatrixT<Scalar> H = design_matrix(positions);
  Eigen::JacobiSVD<DesignMatrixT<Scalar>> svd(H, Eigen::ComputeFullV);
  Vec9T<Scalar> sigma = Vec9T<Scalar>::Zero();
  sigma.head(svd.singularValues().size()) = svd.singularValues();
  V = svd.matrixV();
  const Scalar eps = Eigen::NumTraits<Scalar>::epsilon();
  const Scalar tol = Scalar(std::max<int>(static_cast<int>(positions.size()), 9)) * eps * sigma(0);
  int rank = 0;
  for (int i = 0; i < kParameters; ++i)
    if (sigma(i) > tol) ++rank;
  ev.rank = rank;
  ev.unidentifiable.clear();
  if (rank < kParameters) {
    const auto null_space = V.rightCols(kParameters - rank);
    const Scalar threshold = sqrt(eps);
    for (int r = 0; r < kParameters; ++r)
      if (null_space.row(r).norm() > threshold) ev.unidentifiable.push_back(r);
  }
  return sigma;
}

}  // namespace detail

template <class Scalar>
EvaluationTpl<Scalar> evaluate(const ProgramTpl<Scalar>& program) {
  using std::sqrt;
  EvaluationTpl<Scalar> ev;
  ev.positions = program.size();
  ev.information = information_matrix(program.positions);
  Mat9T<Scalar> V;
  const Vec9T<Scalar> sigma = detail::singular_values(program.positions, ev, V);  // descending
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  if (!ev.full_rank()) {
    ev.condition = inf;
    ev.D = ev.A = ev.E = ev.S = inf;
    ev.theta_bias = ev.theta_scale = ev.theta_nonorth = inf;
    ev.det_K = ev.trace_K = ev.lambda_max_K = ev.max_diag_K = inf;
    ev.K.setZero();
    return ev;
  }
  const Vec9T<Scalar> inv_lambda = sigma.cwiseProduct(sigma).cwiseInverse();  // eigenvalues of K
  ev.K = V * inv_lambda.asDiagonal() * V.transpose();
  const Scalar N(program.size());
  Scalar det_K(1), trace_K(0);
  for (int i = 0; i < kParameters; ++i) {
    det_K *= inv_lambda(i);
    trace_K += inv_lambda(i);
  }
  ev.condition = (sigma(0) / sigma(8)) * (sigma(0) / sigma(8));
  ev.det_K = det_K;
  ev.trace_K = trace_K;
  ev.lambda_max_K = inv_lambda(8);
  const Vec9T<Scalar> diag = ev.K.diagonal();
  ev.max_diag_K = diag.maxCoeff();
  Scalar N9(1);
  for (int i = 0; i < kParameters; ++i) N9 *= N;
  ev.D = N9 * ev.det_K;
  ev.A = N * ev.trace_K;
  ev.E = N * ev.lambda_max_K;
  ev.S = N * ev.max_diag_K;
  ev.theta_bias = sqrt(N * diag.template segment<3>(0).maxCoeff());
  ev.theta_scale = sqrt(N * diag.template segment<3>(3).maxCoeff());
  ev.theta_nonorth = sqrt(N * diag.template segment<3>(6).maxCoeff());
  return ev;
}

}  // namespace scalcal
