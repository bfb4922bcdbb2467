// Gauss-Newton on a thermal log's poses (thermal_calibration.hpp).
#include "numeric/thermal/thermal_calibration.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

Eigen::VectorXd residuals(const std::vector<ThermalPose>& poses, const ThermalFit& f, const Eigen::VectorXd& theta) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(poses.size()));
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Meter meter = f.model.meter_at(theta, f.range.tau(poses[i].celsius), f.magnitude);
    r(static_cast<Eigen::Index>(i)) = meter.compensate(poses[i].mean).norm() / f.magnitude - 1;
  }
  return r;
}

// Central differences: the residuals are smooth in theta and cost nothing next to a log's reading.
Eigen::MatrixXd jacobian(const std::vector<ThermalPose>& poses, const ThermalFit& f, const Eigen::VectorXd& theta) {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(poses.size()), theta.size());
  const double h = 1e-7;
  for (Eigen::Index c = 0; c < theta.size(); ++c) {
    Eigen::VectorXd up = theta, down = theta;
    up(c) += h;
    down(c) -= h;
    J.col(c) = (residuals(poses, f, up) - residuals(poses, f, down)) / (2 * h);
  }
  return J;
}

std::string identifiability(const std::vector<ThermalPose>& poses, const ThermalModel& m) {
  std::set<long long> setpoints;  // to 0.5 degC: the oven's set-points, not each pose's last digits
  for (const auto& p : poses) setpoints.insert(std::llround(2 * p.celsius));
  if (static_cast<int>(setpoints.size()) < m.degree + 1)
    return "the poses' temperatures take " + std::to_string(setpoints.size()) +
           " distinct value(s) (to 0.5 degC): " + m.name() + " needs " + std::to_string(m.degree + 1) +
           " set-points at least; record more set-points or fit a lower degree";
  if (static_cast<int>(poses.size()) <= m.parameters())
    return std::to_string(poses.size()) + " poses for " + std::to_string(m.parameters()) + " parameters of " +
           m.name() + words(": record more poses (`scalcal optimize {model} ") + m.name() + "` designs them)";
  return "";
}

}  // namespace

ThermalFit fit_thermal(const std::vector<ThermalPose>& poses, const ThermalModel& model, const TemperatureRange& range,
                       double magnitude) {
  if (!model_supports(model.base, ModelCapability::thermal_base))
    throw std::invalid_argument("a thermal log is fitted under " + calibrated_thermal_models() + " (got " +
                                model.name() + ")");
  ThermalFit f;
  f.model = model;
  f.range = range;
  f.magnitude = magnitude;
  f.coefficients = Eigen::VectorXd::Zero(model.parameters());
  f.standard_errors = Eigen::VectorXd::Constant(model.parameters(), NAN);
  f.problem = identifiability(poses, model);
  if (!f.problem.empty()) return f;
  Eigen::VectorXd theta = f.coefficients;
  Eigen::VectorXd r = residuals(poses, f, theta);
  double lambda = 1e-6;  // Levenberg's damping, relative to J^T J's diagonal
  for (f.iterations = 1; f.iterations <= 100; ++f.iterations) {
    const Eigen::MatrixXd J = jacobian(poses, f, theta);
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    Eigen::MatrixXd A = JtJ;
    A.diagonal() *= 1 + lambda;
    const Eigen::VectorXd step = A.ldlt().solve(-g);
    const Eigen::VectorXd trial = theta + step;
    const Eigen::VectorXd rt = residuals(poses, f, trial);
    if (rt.squaredNorm() <= r.squaredNorm()) {
      theta = trial;
      r = rt;
      lambda = std::max(lambda / 10, 1e-12);
      if (step.norm() <= 1e-12 * (1 + theta.norm())) {
        f.converged = true;
        break;
      }
    } else {
      lambda *= 10;
      if (lambda > 1e8) break;
    }
  }
  const Eigen::MatrixXd J = jacobian(poses, f, theta);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J.transpose() * J);
  const Eigen::VectorXd& l = eig.eigenvalues();
  f.condition = l(l.size() - 1) / l(0);
  f.coefficients = theta;
  f.residuals.assign(r.data(), r.data() + r.size());
  f.rms = std::sqrt(r.squaredNorm() / static_cast<double>(r.size()));
  if (!(l(0) > 1e-12 * l(l.size() - 1))) {
    f.problem = "the poses cannot identify " + model.name() + " (J^T J's condition " + std::to_string(f.condition) +
                "): spread the positions over the sphere at every set-point";
    return f;
  }
  if (!f.converged) {
    f.problem = "Gauss-Newton did not converge in 100 iterations; check the magnitude and the poses";
    return f;
  }
  const double dof = static_cast<double>(r.size() - theta.size());
  const double sigma2 = r.squaredNorm() / dof;
  const Eigen::MatrixXd cov =
      eig.eigenvectors() * (sigma2 * l.cwiseInverse()).asDiagonal() * eig.eigenvectors().transpose();
  f.standard_errors = cov.diagonal().cwiseSqrt();
  return f;
}

}  // namespace scalcal
