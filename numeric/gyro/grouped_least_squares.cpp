// Levenberg-Marquardt with variance components (grouped_least_squares.hpp).
#include "numeric/gyro/grouped_least_squares.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace scalcal::gyro {
namespace {

// The problem's residuals with each group's weight 1/scale applied.
struct Weighted {
  const GroupedProblem& P;
  std::vector<double> weight;  // sqrt(1 / scale) per group
  void operator()(const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J) const {
    P.evaluate(p, r, J);
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      const double w = weight[static_cast<std::size_t>(P.row_group[static_cast<std::size_t>(i)])];
      r(i) *= w;
      if (J) J->row(i) *= w;
    }
  }
};

int minimise(const Weighted& f, Eigen::VectorXd& p, int max_iterations, Summary& summary) {
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  f(p, r, &J);
  double cost = r.squaredNorm(), lambda = 1e-4;
  summary.termination = Termination::not_converged;
  summary.message = "the iteration limit was reached";
  for (int it = 1; it <= max_iterations; ++it) {
    const Eigen::MatrixXd N = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    const Eigen::VectorXd d = N.diagonal().cwiseMax(1e-300);
    bool stepped = false;
    for (int tries = 0; tries < 40 && !stepped; ++tries) {
      Eigen::MatrixXd A = N;
      A.diagonal() += lambda * d;
      const Eigen::VectorXd step = -A.ldlt().solve(g);
      const Eigen::VectorXd next = p + step;
      Eigen::VectorXd rn;
      f(next, rn, nullptr);
      const double cn = rn.squaredNorm();
      if (std::isfinite(cn) && cn <= cost) {
        const bool small =
            step.cwiseProduct(d.cwiseSqrt()).norm() < 1e-9 * (1 + std::sqrt(cost)) || cost - cn < 1e-15 * cost;
        p = next;
        stepped = true;
        lambda = std::max(lambda / 10, 1e-12);
        f(p, r, &J);
        cost = r.squaredNorm();
        if (small) {
          summary = {Termination::converged, "converged", it};
          return it;
        }
      } else {
        lambda *= 10;
      }
    }
    if (!stepped) {
      summary = {Termination::converged, "converged (no step lowers the misfit further in this precision)", it};
      return it;
    }
  }
  summary.iterations = max_iterations;
  return max_iterations;
}

Eigen::MatrixXd inverse_normal(const Eigen::MatrixXd& J) {
  const Eigen::MatrixXd N = J.transpose() * J;
  return N.ldlt().solve(Eigen::MatrixXd::Identity(N.rows(), N.cols()));
}

}  // namespace

GroupedFit fit_grouped(const GroupedProblem& P, const Eigen::VectorXd& start, int max_iterations) {
  GroupedFit out;
  out.p = start;
  Weighted f{P, std::vector<double>(static_cast<std::size_t>(P.groups), 1.0)};
  std::vector<double> scale(static_cast<std::size_t>(P.groups), 1.0);
  for (int pass = 0; pass < 8; ++pass) {
    out.iterations += minimise(f, out.p, max_iterations, out.summary);
    // Each group's chi-square against the predicted noise and its degrees of freedom.
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    f(out.p, r, &J);
    const Eigen::MatrixXd S = inverse_normal(J) * J.transpose();
    out.chi_square.assign(static_cast<std::size_t>(P.groups), 0.0);
    out.dof.assign(static_cast<std::size_t>(P.groups), 0.0);
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      const auto g = static_cast<std::size_t>(P.row_group[static_cast<std::size_t>(i)]);
      out.chi_square[g] += r(i) * r(i) * scale[g];  // undo the weight: against the predicted noise
      out.dof[g] += 1 - J.row(i).dot(S.col(i));
    }
    bool settled = true;
    for (std::size_t g = 0; g < scale.size(); ++g) {
      const double s = out.dof[g] > 0.5 ? std::max(1.0, out.chi_square[g] / out.dof[g]) : scale[g];
      settled = settled && std::abs(s / scale[g] - 1) < 1e-3;
      scale[g] = s;
      f.weight[g] = 1 / std::sqrt(s);
    }
    if (settled) break;
  }
  out.scale = scale;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  f(out.p, r, &J);
  out.covariance = inverse_normal(J);
  out.standard_error = out.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  P.evaluate(out.p, r, &J);
  out.predicted_std = inverse_normal(J).diagonal().cwiseMax(0.0).cwiseSqrt();
  // Condition of the normal matrix with unit diagonal: how well the data determine the parameters.
  Eigen::MatrixXd N = J.transpose() * J;
  const Eigen::VectorXd d = N.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  N = d.asDiagonal() * N * d.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(N, Eigen::EigenvaluesOnly);
  out.rank_condition = es.eigenvalues().maxCoeff() / std::max(es.eigenvalues().minCoeff(), 1e-300);
  return out;
}

}  // namespace scalcal::gyro
