// Scalar calibration under any registered model (model_calibration.hpp).
#include "numeric/calibration/model_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "numeric/calibration/monte_carlo.hpp"

namespace scalcal {

MeterSlots meter_slots(ModelKind model) {
  return visit_model(model, [](auto M) {
    using Model = decltype(M);
    using MeterType = typename Model::meter;
    MeterSlots out;
    for (int m : meter_index_of<Model>()) {
      const MeterParameter& p = MeterType::kParameters[static_cast<std::size_t>(m)];
      out.push_back({m, p, MeterType::linear_group(p.group)});
    }
    return out;
  });
}

std::vector<int> meter_group(const MeterSlots& slots, ParameterGroup g) {
  std::vector<int> out(3, -1);
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k].parameter.group == g) out[static_cast<std::size_t>(slots[k].parameter.axis)] = static_cast<int>(k);
  return std::count(out.begin(), out.end(), -1) == 0 ? out : std::vector<int>{};
}

bool has_meter_group(const MeterSlots& slots, ParameterGroup g) {
  return std::any_of(slots.begin(), slots.end(), [g](const MeterSlot& s) { return s.parameter.group == g; });
}

bool corrects_linearly(const MeterSlots& slots) {
  return std::all_of(slots.begin(), slots.end(), [](const MeterSlot& s) { return s.linear; });
}

std::string_view meter_units_bound(ModelKind model) {
  return visit_model(model, [](auto M) -> std::string_view {
    using ModelMeter = typename decltype(M)::meter;
    if constexpr (requires { ModelMeter::units_bound; }) return ModelMeter::units_bound;
    return "its correction is not a matrix and an offset";
  });
}

AnyMeter model_meter(ModelKind model, const Eigen::VectorXd& X, double magnitude) {
  return visit_model(model, [&](auto M) {
    using Model = decltype(M);
    using MeterType = typename Model::meter;
    constexpr auto index = meter_index_of<Model>();
    Eigen::Matrix<double, static_cast<int>(MeterType::kParameters.size()), 1> full;
    full.setZero();
    for (std::size_t k = 0; k < index.size(); ++k) full(index[k]) = X(static_cast<Eigen::Index>(k));
    return AnyMeter(MeterType::from_parameters(full, magnitude));
  });
}

namespace {

using RowFunction = Eigen::VectorXd (*)(const Vec3&);

template <class Model>
Eigen::VectorXd dynamic_row(const Vec3& eta) {
  return Model::row(eta);
}

}  // namespace

namespace {

// The residuals J_i = m_i / |I| - 1 of one data set under one model, the quantities the estimator
// needs of them, and nothing else.
struct ModelResiduals {
  const std::vector<PositionSamples>& data;
  const CalibrationOptions& options;
  ModelKind model;
  RowFunction row;
  std::vector<Vec3> means;
  std::vector<double> weights;

  int parameters() const { return model_parameters(model); }
  AnyMeter meter_of(const Eigen::VectorXd& X) const { return model_meter(model, X, options.magnitude); }
  double modulus(const Vec3& c, std::size_t i) const {
    return options.modulus == Modulus::norm ? c.norm() : c.dot(*data[i].nominal);
  }
  Vec3 direction(const Vec3& c, std::size_t i) const {
    return options.modulus == Modulus::norm ? Vec3(c.normalized()) : Vec3(data[i].nominal->normalized());
  }
  Eigen::VectorXd at(const Eigen::VectorXd& X) const {
    const AnyMeter meter = meter_of(X);
    Eigen::VectorXd J(static_cast<Eigen::Index>(means.size()));
    for (std::size_t i = 0; i < means.size(); ++i)
      J(static_cast<Eigen::Index>(i)) = modulus(meter.compensate(means[i]), i) / options.magnitude - 1;
    return J;
  }
  double cost(const Eigen::VectorXd& J) const {
    double c = 0;
    for (Eigen::Index i = 0; i < J.size(); ++i) c += weights[static_cast<std::size_t>(i)] * J(i) * J(i);
    return c;
  }
  // dJ/dX by central differences: the paper's rows -h (eq. 6) are its first-order form at X = 0;
  // away from it (a meter far from the start, large residuals) only the derivative itself makes
  // every Gauss-Newton step a descent direction of sum w J^2.
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& X) const {
    constexpr double kStep = 1e-6;  // X is dimensionless and small: central differences exact to ~1e-12
    Eigen::MatrixXd D(static_cast<Eigen::Index>(means.size()), parameters());
    for (int k = 0; k < parameters(); ++k) {
      Eigen::VectorXd a = X, b = X;
      a(k) += kStep;
      b(k) -= kStep;
      D.col(k) = (at(a) - at(b)) / (2 * kStep);
    }
    return D;
  }
  // The paper's step (eq. 6): J ~ h.(X_true - X), fitted by weighted least squares.
  Eigen::VectorXd paper_step(const Eigen::VectorXd& X, const Eigen::VectorXd& J) const {
    const AnyMeter meter = meter_of(X);
    Eigen::MatrixXd info = Eigen::MatrixXd::Zero(parameters(), parameters());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(parameters());
    for (std::size_t i = 0; i < means.size(); ++i) {
      const Eigen::VectorXd h = row(direction(meter.compensate(means[i]), i));
      info += weights[i] * h * h.transpose();
      rhs += weights[i] * J(static_cast<Eigen::Index>(i)) * h;
    }
    return info.ldlt().solve(rhs);
  }
  // sum w h h^T at the estimate with the model's rows: the paper's information matrix, whose
  // inverse every criterion judges.
  Eigen::MatrixXd information(const AnyMeter& meter, bool by_samples) const {
    Eigen::MatrixXd info = Eigen::MatrixXd::Zero(parameters(), parameters());
    for (std::size_t i = 0; i < means.size(); ++i) {
      const Eigen::VectorXd h = row(direction(meter.compensate(means[i]), i));
      info += (by_samples ? weights[i] : 1.0 / static_cast<double>(data[i].samples.size())) * h * h.transpose();
    }
    return info;
  }
};

// Within this of zero every parameter stays (bias over |I|, scale deviation, gamma, c |I|): the
// start has brought the data near the field's units, and beyond it the linearised model of eq. (2)
// is not a meter any more (an axis tilted by 30 degrees, a gain off by half).
constexpr double kModelEdge = 0.5;

// The paper's iteration (eq. 6) with a backtracking line search on sum w J^2: a step that does not
// lower the residual is halved, so the iteration cannot run away. Where the paper's step (its rows
// h are dJ/dX to first order only) no longer lowers the residual, Gauss-Newton with the exact
// derivative takes over from there, to the least-squares minimum itself. A step that would leave
// |X| < kModelEdge is refused; none that lowers the residual ends the iteration, converged only
// when the step is already at the precision's floor.
Eigen::VectorXd damped_gauss_newton(const ModelResiduals& f, int max_iterations, double tolerance, Summary& summary) {
  Eigen::VectorXd X = Eigen::VectorXd::Zero(f.parameters());
  Eigen::VectorXd J = f.at(X);
  double cost = f.cost(J);
  summary.termination = Termination::not_converged;
  summary.message = "the iteration limit was reached";
  const Eigen::VectorXd w =
      Eigen::Map<const Eigen::VectorXd>(f.weights.data(), static_cast<Eigen::Index>(f.weights.size()));
  bool exact = false;
  for (summary.iterations = 1; summary.iterations <= max_iterations; ++summary.iterations) {
    if (!std::isfinite(cost)) {
      summary.termination = Termination::failed;
      summary.message = "the residuals are not finite at the start (a position the model cannot invert)";
      break;
    }
    Eigen::VectorXd dX;
    if (exact) {
      const Eigen::MatrixXd D = f.jacobian(X);
      const Eigen::MatrixXd WD = w.asDiagonal() * D;
      dX = -(D.transpose() * WD).ldlt().solve(WD.transpose() * J);
    } else {
      dX = f.paper_step(X, J);
    }
    double t = 1;
    bool accepted = false;
    bool edge = false;
    for (int halvings = 0; halvings < 30 && dX.allFinite(); ++halvings, t /= 2) {
      const Eigen::VectorXd next = X + t * dX;
      if (next.cwiseAbs().maxCoeff() >= kModelEdge) {
        edge = true;
        continue;
      }
      const Eigen::VectorXd Jn = f.at(next);
      const double c = f.cost(Jn);
      if (std::isfinite(c) && c <= cost) {
        X = next;
        J = Jn;
        cost = c;
        accepted = true;
        break;
      }
    }
    const double step = accepted ? (t * dX).cwiseAbs().maxCoeff() : dX.cwiseAbs().maxCoeff();
    if (step < tolerance || (!accepted && step < std::sqrt(tolerance))) {
      summary.termination = Termination::converged;
      summary.message = "converged";
      break;
    }
    if (!accepted && !exact) {
      exact = true;  // the paper's step has done what it can: the exact derivative from here
      continue;
    }
    if (!accepted) {
      summary.message = edge ? "the estimate runs to the edge of the linearised model (a parameter at " +
                                   std::to_string(kModelEdge) +
                                   "): these data are far from the model (a mislabelled or wrong position?)"
                             : "no step along the Gauss-Newton direction lowers the residual (the model does not fit "
                               "these data)";
      break;
    }
  }
  summary.iterations = std::min(summary.iterations, max_iterations);
  return X;
}

}  // namespace

ModelCalibration calibrate_model(ModelKind model, const std::vector<PositionSamples>& data,
                                 const CalibrationOptions& options) {
  ModelResiduals f{data,  options,
                   model, visit_model(model, [](auto M) -> RowFunction { return &dynamic_row<decltype(M)>; }),
                   {},    {}};
  for (const auto& p : data) {
    f.means.push_back(p.mean());
    f.weights.push_back(options.weight_by_samples ? static_cast<double>(p.samples.size()) : 1.0);
  }
  const int P = f.parameters();
  const double magnitude = options.magnitude;
  ModelCalibration r;
  r.model = model;
  r.positions = static_cast<int>(data.size());
  for (const auto& p : data) r.samples += static_cast<int>(p.samples.size());
  r.X = damped_gauss_newton(f, options.max_iterations, options.tolerance, r.summary);
  r.iterations = r.summary.iterations;
  r.meter = f.meter_of(r.X);
  r.K = f.information(r.meter, true).ldlt().solve(Eigen::MatrixXd::Identity(P, P));
  // Equal weights: the covariance of X is K (sum h h^T / n_i) K per unit of a sample's variance.
  if (!options.weight_by_samples) r.K = r.K * f.information(r.meter, false) * r.K;
  const Eigen::VectorXd J = f.at(r.X);
  r.residual_rms = std::sqrt(J.squaredNorm() / r.positions) * magnitude;
  if (r.samples > r.positions) {
    double scatter = 0;
    for (std::size_t i = 0; i < data.size(); ++i) {
      std::vector<double> m;
      double mean = 0;
      for (const auto& s : data[i].samples) {
        m.push_back(f.modulus(r.meter.compensate(s), i));
        mean += m.back();
      }
      mean /= static_cast<double>(m.size());
      for (double v : m) scatter += (v - mean) * (v - mean);
    }
    r.noise = std::sqrt(scatter / (r.samples - r.positions));
    r.noise_source = NoiseSource::scatter;
  } else if (r.positions > P) {
    r.noise = std::sqrt(J.squaredNorm() / (r.positions - P)) * magnitude;
    r.noise_source = NoiseSource::residuals;
  }
  r.X_std = Eigen::VectorXd::Zero(P);
  if (r.noise_source != NoiseSource::none)
    for (int k = 0; k < P; ++k) r.X_std(k) = r.noise / magnitude * std::sqrt(r.K(k, k));
  return r;
}

AnyMeter reference_model_meter(ModelKind model, double size) {
  return visit_model(model, [model, size](auto M) {
    using Model = decltype(M);
    using MeterType = typename Model::meter;
    const MeterType full = MeterType::reference(reference_meter(size), size);
    const auto all = full.parameters(1.0);
    constexpr auto index = meter_index_of<Model>();
    Eigen::VectorXd X(static_cast<Eigen::Index>(index.size()));
    for (std::size_t k = 0; k < index.size(); ++k) X(static_cast<Eigen::Index>(k)) = all(index[k]);
    AnyMeter m = model_meter(model, X, 1.0);  // the model's parameters of it, its meter's others zero
    // The rotation part of the reference misalignment stays: invisible to every scalar model.
    const Mat3 A = full.linear.misalignment;
    const Mat3 rotation = (A - A.transpose()) / 2;
    m.as<MeterType>()->linear.misalignment += rotation;
    return m;
  });
}

}  // namespace scalcal
