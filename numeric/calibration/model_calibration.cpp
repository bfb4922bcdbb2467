#include "numeric/calibration/model_calibration.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "numeric/calibration/monte_carlo.hpp"

namespace scalcal {

using Vec12 = Eigen::Matrix<double, 12, 1>;

Vec3 ModelMeter::measure(const Vec3& I) const {
  const Vec3 a = linear.phi() * I;
  Vec3 y;
  for (int i = 0; i < 3; ++i) y(i) = linear.bias(i) + (1 + linear.scale_deviation(i)) * a(i) + cubic(i) * a(i) * a(i);
  return y;
}

Vec3 ModelMeter::compensate(const Vec3& measured) const {
  Vec3 a;
  for (int i = 0; i < 3; ++i) {
    const double r = measured(i) - linear.bias(i), g = 1 + linear.scale_deviation(i);
    const double disc = g * g + 4 * cubic(i) * r;
    // g a + c a^2 = r, the root that tends to r / g as c -> 0, in the form free of cancellation.
    a(i) = disc >= 0 ? 2 * r / (g + std::sqrt(disc)) : std::numeric_limits<double>::quiet_NaN();
  }
  return linear.phi().inverse() * a;
}

Vec12 ModelMeter::parameters(double magnitude) const {
  Vec12 X;
  X << linear.parameters(magnitude), cubic * magnitude;
  return X;
}

ModelMeter ModelMeter::from_parameters(const Vec12& X, double magnitude) {
  ModelMeter m;
  m.linear = Meter::from_parameters(X.head<9>(), magnitude);
  m.cubic = X.tail<3>() / magnitude;
  return m;
}

std::vector<int> meter_indices(ModelKind model) {
  return visit_model(model, [&](auto M) {
    using Model = decltype(M);
    std::vector<int> out;
    for (std::string_view name : Model::parameter_names) {
      int k = 0;
      while (k < 12 && kMeterParameterNames[static_cast<std::size_t>(k)] != name) ++k;
      if (k == 12)
        throw std::invalid_argument("model " + std::string(Model::name) + ": the meter model has no parameter '" +
                                    std::string(name) + "'");
      out.push_back(k);
    }
    return out;
  });
}

namespace {

using RowFunction = Eigen::VectorXd (*)(const Vec3&);

template <class Model>
Eigen::VectorXd dynamic_row(const Vec3& eta) {
  return Model::row(eta);
}

}  // namespace

ModelCalibration calibrate_model(ModelKind model, const std::vector<PositionSamples>& data,
                                 const CalibrationOptions& options) {
  const RowFunction row = visit_model(model, [](auto M) -> RowFunction { return &dynamic_row<decltype(M)>; });
  const std::vector<int> index = meter_indices(model);
  const int P = static_cast<int>(index.size());
  const double magnitude = options.magnitude;
  ModelCalibration r;
  r.model = model;
  r.positions = static_cast<int>(data.size());
  for (const auto& p : data) r.samples += static_cast<int>(p.samples.size());
  std::vector<Vec3> means;
  for (const auto& p : data) means.push_back(p.mean());

  const auto meter_of = [&](const Eigen::VectorXd& X) {
    Vec12 full = Vec12::Zero();
    for (int k = 0; k < P; ++k) full(index[static_cast<std::size_t>(k)]) = X(k);
    return ModelMeter::from_parameters(full, magnitude);
  };
  const auto direction = [&](const Vec3& c, std::size_t i) -> Vec3 {
    return options.modulus == Modulus::norm ? Vec3(c.normalized()) : Vec3(data[i].nominal->normalized());
  };
  const auto modulus = [&](const Vec3& c, std::size_t i) {
    return options.modulus == Modulus::norm ? c.norm() : c.dot(*data[i].nominal);
  };
  Eigen::VectorXd X = Eigen::VectorXd::Zero(P);
  Eigen::MatrixXd info(P, P);
  std::vector<double> J(data.size());
  const auto residuals = [&](const Eigen::VectorXd& at) {
    const ModelMeter meter = meter_of(at);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(P);
    info.setZero();
    for (std::size_t i = 0; i < data.size(); ++i) {
      const Vec3 c = meter.compensate(means[i]);
      J[i] = modulus(c, i) / magnitude - 1;
      const double w = options.weight_by_samples ? static_cast<double>(data[i].samples.size()) : 1.0;
      const Eigen::VectorXd h = row(direction(c, i));
      info += w * h * h.transpose();
      rhs += w * J[i] * h;
    }
    return rhs;
  };
  for (r.iterations = 1; r.iterations <= options.max_iterations; ++r.iterations) {
    const Eigen::VectorXd rhs = residuals(X);
    // J = m/|I| - 1 ~ h.(X_true - X): the step is the least-squares fit of the residual (6).
    const Eigen::VectorXd dX = info.ldlt().solve(rhs);
    X += dX;
    if (!X.allFinite() || X.cwiseAbs().maxCoeff() >= 0.5) break;  // diverged: outside the linearisation
    if (dX.cwiseAbs().maxCoeff() < options.tolerance) {
      r.converged = true;
      break;
    }
  }
  if (r.iterations > options.max_iterations) r.iterations = options.max_iterations;
  r.X = X;
  r.meter = meter_of(X);
  residuals(X);
  r.K = Eigen::LDLT<Eigen::MatrixXd>(info).solve(Eigen::MatrixXd::Identity(P, P));
  if (!options.weight_by_samples) {  // as calibrate(): K (sum h h^T / n_i) K per unit sample variance
    Eigen::MatrixXd middle = Eigen::MatrixXd::Zero(P, P);
    for (std::size_t i = 0; i < data.size(); ++i) {
      const Eigen::VectorXd h = row(direction(r.meter.compensate(means[i]), i));
      middle += h * h.transpose() / static_cast<double>(data[i].samples.size());
    }
    r.K = r.K * middle * r.K;
  }
  double ss = 0;
  for (double j : J) ss += j * j;
  r.residual_rms = std::sqrt(ss / r.positions) * magnitude;
  if (r.samples > r.positions) {
    double scatter = 0;
    for (std::size_t i = 0; i < data.size(); ++i) {
      std::vector<double> m;
      double mean = 0;
      for (const auto& s : data[i].samples) {
        m.push_back(modulus(r.meter.compensate(s), i));
        mean += m.back();
      }
      mean /= static_cast<double>(m.size());
      for (double v : m) scatter += (v - mean) * (v - mean);
    }
    r.noise = std::sqrt(scatter / (r.samples - r.positions));
    r.noise_source = NoiseSource::scatter;
  } else if (r.positions > P) {
    r.noise = std::sqrt(ss / (r.positions - P)) * magnitude;
    r.noise_source = NoiseSource::residuals;
  }
  r.X_std = Eigen::VectorXd::Zero(P);
  if (r.noise_source != NoiseSource::none)
    for (int k = 0; k < P; ++k) r.X_std(k) = r.noise / magnitude * std::sqrt(r.K(k, k));
  return r;
}

ModelMeter reference_model_meter(ModelKind model, double size) {
  ModelMeter full;
  full.linear = reference_meter(size);
  full.cubic = size * Vec3(0.9, -0.6, 1.3);
  const Vec12 X = full.parameters(1.0);
  Vec12 kept = Vec12::Zero();
  for (int k : meter_indices(model)) kept(k) = X(k);
  ModelMeter m = ModelMeter::from_parameters(kept, 1.0);
  // The rotation part of the reference misalignment stays: invisible to every scalar model.
  const Mat3 A = full.linear.misalignment;
  const Mat3 rotation = (A - A.transpose()) / 2;
  m.linear.misalignment += rotation;
  return m;
}

}  // namespace scalcal
