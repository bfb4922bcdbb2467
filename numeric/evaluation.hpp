// Evaluation of a program as the paper compares programs: K = (H^T H)^-1 and the D, A, E and
// max-diagonal criteria, normalised by N (D by N^9), and the RMS errors theta_q (eq. 7). A
// program whose H is rank-deficient is reported with its rank and the parameters it cannot
// identify; criteria are then +infinity, never a regularised number.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "numeric/design.hpp"
#include "numeric/parameters.hpp"
#include "numeric/program.hpp"

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

// Rank of H by its singular values, with the usual tolerance max(N, 9) eps sigma_max; the
// parameters whose unit vector has a component in the null space are not identifiable.
template <class Scalar>
void rank_and_identifiability(const std::vector<Vec3T<Scalar>>& positions, EvaluationTpl<Scalar>& ev) {
  using std::abs;
  using std::sqrt;
  const DesignMatrixT<Scalar> H = design_matrix(positions);
  Eigen::JacobiSVD<DesignMatrixT<Scalar>> svd(H, Eigen::ComputeFullV);
  const auto& sigma = svd.singularValues();
  const Scalar eps = Eigen::NumTraits<Scalar>::epsilon();
  const Scalar tol = Scalar(std::max<int>(static_cast<int>(positions.size()), 9)) * eps *
                     (sigma.size() > 0 ? sigma(0) : Scalar(0));
  int rank = 0;
  for (Eigen::Index i = 0; i < sigma.size(); ++i)
    if (sigma(i) > tol) ++rank;
  ev.rank = rank;
  ev.unidentifiable.clear();
  if (rank == kParameters) return;
  const auto null_space = svd.matrixV().rightCols(kParameters - rank);
  const Scalar threshold = sqrt(eps);
  for (int r = 0; r < kParameters; ++r)
    if (null_space.row(r).norm() > threshold) ev.unidentifiable.push_back(r);
}

}  // namespace detail

template <class Scalar>
EvaluationTpl<Scalar> evaluate(const ProgramTpl<Scalar>& program) {
  using std::sqrt;
  EvaluationTpl<Scalar> ev;
  ev.positions = program.size();
  ev.information = information_matrix(program.positions);
  detail::rank_and_identifiability(program.positions, ev);
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  if (!ev.full_rank()) {
    ev.condition = inf;
    ev.D = ev.A = ev.E = ev.S = inf;
    ev.theta_bias = ev.theta_scale = ev.theta_nonorth = inf;
    ev.det_K = ev.trace_K = ev.lambda_max_K = ev.max_diag_K = inf;
    ev.K.setZero();
    return ev;
  }
  // The information matrix is symmetric positive definite: its eigen-decomposition gives K,
  // det K, trace K and lambda_max(K) from the same factorisation, accurately for any scalar.
  Eigen::SelfAdjointEigenSolver<Mat9T<Scalar>> eig(ev.information);
  const Vec9T<Scalar> lambda = eig.eigenvalues();  // ascending
  const Mat9T<Scalar>& V = eig.eigenvectors();
  ev.K = V * lambda.cwiseInverse().asDiagonal() * V.transpose();
  const Scalar N(program.size());
  Scalar det_M(1), trace_K(0);
  for (int i = 0; i < kParameters; ++i) {
    det_M *= lambda(i);
    trace_K += Scalar(1) / lambda(i);
  }
  ev.condition = lambda(8) / lambda(0);
  ev.det_K = Scalar(1) / det_M;
  ev.trace_K = trace_K;
  ev.lambda_max_K = Scalar(1) / lambda(0);
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
