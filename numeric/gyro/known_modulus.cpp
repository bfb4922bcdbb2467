// Rate tables and known turns: items of known modulus, the model's parameters, the fit
// (known_modulus.hpp).
#include "numeric/gyro/known_modulus.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/model_choice.hpp"
#include "numeric/gyro/grouped_least_squares.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal::gyro {

std::vector<ModulusItem> segment_items(const std::vector<LogInterval>& segments, const std::vector<double>& rates) {
  std::vector<ModulusItem> out;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const LogInterval& s = segments[i];
    ModulusItem it;
    it.mean = s.mean;
    it.modulus = rates.size() == 1 ? rates[0] : rates[i];
    // The mean's error along its direction: one sample's scatter (the axes' mean) over sqrt(n).
    it.noise = s.sd.norm() / std::sqrt(3.0 * std::max(1, s.samples));
    it.line = s.line;
    it.start = s.span.start;
    it.stop = s.span.stop;
    out.push_back(it);
  }
  return out;
}

std::vector<ModulusItem> turn_items(const std::vector<Turn>& turns, const std::vector<double>& angles,
                                    double sample_noise, double sample_period) {
  std::vector<ModulusItem> out;
  for (std::size_t i = 0; i < turns.size(); ++i) {
    const Turn& t = turns[i];
    ModulusItem it;
    it.mean = t.integral / t.seconds;
    it.modulus = (angles.size() == 1 ? angles[0] : angles[i]) / t.seconds;
    // White noise of one sample integrated over the turn (an angle random walk), per unit of time.
    it.noise = sample_noise * std::sqrt(sample_period * t.seconds) / t.seconds;
    it.line = t.line;
    out.push_back(it);
  }
  return out;
}

namespace {

using Full = Eigen::Matrix<double, 9, 1>;

// Which of the nine (o, k, gamma) a model frees, by its parameters' groups in the meter: the offsets always; a
// gain per axis with its scale factors, else one gain for the three (bias3: offsets only, so the rate's scale is
// one unknown); the gammas with its non-orthogonality. paper9 frees 9, axis6 6, bias3 4.
struct Layout {
  std::string name;
  bool gains = true, gammas = true;
  int free = 9;
  Full expand(const Eigen::VectorXd& p) const {
    Full x = Full::Zero();
    x.head<3>() = p.head<3>();
    if (!gains) {
      x.segment<3>(3).setConstant(p(3));
    } else {
      x.segment<3>(3) = p.segment<3>(3);
      if (gammas) x.tail<3>() = p.tail<3>();
    }
    return x;
  }
  Eigen::VectorXd reduce(const Full& x) const {
    Eigen::VectorXd p(free);
    p.head<3>() = x.head<3>();
    if (!gains) {
      p(3) = std::cbrt(x(3) * x(4) * x(5));
    } else {
      p.segment<3>(3) = x.segment<3>(3);
      if (gammas) p.tail<3>() = x.tail<3>();
    }
    return p;
  }
  // d full / d reduced (9 x free), constant.
  Eigen::MatrixXd map() const {
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(9, free);
    for (int i = 0; i < 3; ++i) M(i, i) = 1;
    for (int i = 0; i < 3; ++i) M(3 + i, gains ? 3 + i : 3) = 1;
    if (gammas)
      for (int i = 0; i < 3; ++i) M(6 + i, 6 + i) = 1;
    return M;
  }
};

Layout layout_of(ModelKind model) {
  const MeterSlots slots = meter_slots(model);
  Layout L;
  L.name = model_name(model);
  L.gains = has_meter_group(slots, ParameterGroup::scale);
  L.gammas = has_meter_group(slots, ParameterGroup::nonorth);
  const bool offsets = meter_group(slots, ParameterGroup::bias).size() == 3;
  if (!offsets || !corrects_linearly(slots) || (L.gammas && !L.gains))
    throw std::invalid_argument("a gyro's rate table or turns take the models " +
                                models_supporting(ModelCapability::auto_choice) + ", not " + L.name);
  L.free = 3 + (L.gains ? 3 : 1) + (L.gammas ? 3 : 0);
  return L;
}

Meter meter_of(const Full& x) {
  Vec9 X;
  X << Vec3::Zero(), x.segment<3>(3) - Vec3::Ones(), x.tail<3>();
  Meter m = Meter::from_parameters(X, 1.0);
  m.bias = x.head<3>();
  return m;
}

// The start: o from the rests (else the items' mean, right for a table turned both ways), one gain
// from the items' moduli, or the ellipsoid through the items when they share one modulus.
Full start_of(const std::vector<ModulusItem>& items, const std::vector<LogInterval>& rests) {
  Full x = Full::Zero();
  Vec3 o = Vec3::Zero();
  if (!rests.empty()) {
    for (const auto& r : rests) o += r.mean;
    o /= static_cast<double>(rests.size());
  } else {
    for (const auto& it : items) o += it.mean;
    o /= static_cast<double>(items.size());
  }
  bool one_modulus = items.size() >= 9;
  for (const auto& it : items) one_modulus = one_modulus && std::abs(it.modulus / items[0].modulus - 1) < 1e-9;
  if (one_modulus && rests.empty()) {
    std::vector<Vec3> means;
    for (const auto& it : items) means.push_back(it.mean);
    if (const auto e = fit_ellipsoid(means, items[0].modulus))
      if (const auto c = canonical_correction(e->matrix, e->offset)) {
        x.head<3>() = c->offset;
        x.segment<3>(3) = c->scale;
        x.tail<3>() = c->nonorthogonality;
        return x;
      }
  }
  std::vector<double> gains;
  for (const auto& it : items) gains.push_back((it.mean - o).norm() / it.modulus);
  std::nth_element(gains.begin(), gains.begin() + static_cast<std::ptrdiff_t>(gains.size() / 2), gains.end());
  x.head<3>() = o;
  x.segment<3>(3).setConstant(gains[gains.size() / 2]);
  return x;
}

}  // namespace

KnownModulusCalibration calibrate_known_moduli(const std::string& file, const std::vector<ModulusItem>& items,
                                               const std::vector<LogInterval>& rests,
                                               const KnownModulusOptions& options) {
  const Layout L = layout_of(options.model);
  const int n = static_cast<int>(items.size());
  const int observations = n + (rests.empty() ? 0 : 3);
  if (n == 0 || observations < L.free)
    throw InputError(file, 0,
                     "found " + std::to_string(n) + " segments or turns and " + std::to_string(rests.size()) +
                         words(" rests; {model} ") + L.name + " needs at least " + std::to_string(L.free) +
                         " of them (the rests count as 3, for the offset)");
  const Full x0 = start_of(items, rests);
  const double gain0 = std::cbrt(std::abs(x0(3) * x0(4) * x0(5)));  // raw units per physical unit
  const Eigen::MatrixXd dmap = L.map();

  GroupedProblem P;
  P.parameters = L.free;
  P.groups = rests.empty() ? 1 : 2;
  P.row_group.assign(static_cast<std::size_t>(n), 0);
  if (!rests.empty()) P.row_group.resize(static_cast<std::size_t>(n + 3 * static_cast<int>(rests.size())), 1);
  // Residuals in units of each one's predicted noise; the Jacobian by central differences in the
  // full nine (o, k, gamma) with steps of 1e-6 of each one's scale, then mapped to the model's.
  auto residuals = [&](const Full& x, Eigen::VectorXd& r) {
    const Meter m = meter_of(x);
    r.resize(static_cast<Eigen::Index>(P.row_group.size()));
    for (int i = 0; i < n; ++i) {
      const ModulusItem& it = items[static_cast<std::size_t>(i)];
      r(i) = (m.compensate(it.mean).norm() - it.modulus) * gain0 / it.noise;
    }
    for (std::size_t j = 0; j < rests.size(); ++j)
      for (int c = 0; c < 3; ++c)
        r(n + 3 * static_cast<int>(j) + c) = (rests[j].mean(c) - x(c)) *
                                             std::sqrt(static_cast<double>(rests[j].samples)) /
                                             std::max(rests[j].sd(c), 1e-300);
  };
  Full step;
  double top = 0;
  for (const auto& it : items) top = std::max(top, it.modulus);
  step << Vec3::Constant(1e-6 * gain0 * top), Vec3::Constant(1e-6 * gain0), Vec3::Constant(1e-6);
  P.evaluate = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    const Full x = L.expand(p);
    residuals(x, r);
    if (!J) return;
    Eigen::MatrixXd Jf(r.size(), 9);
    for (int j = 0; j < 9; ++j) {
      Full a = x, b = x;
      a(j) += step(j);
      b(j) -= step(j);
      Eigen::VectorXd ra, rb;
      residuals(a, ra);
      residuals(b, rb);
      Jf.col(j) = (ra - rb) / (2 * step(j));
    }
    *J = Jf * dmap;
  };
  const GroupedFit fit = fit_grouped(P, L.reduce(x0), options.max_iterations);

  KnownModulusCalibration out;
  out.model = options.model;
  out.parameters = L.expand(fit.p);
  out.meter = meter_of(out.parameters);
  out.correction = correction_of(out.meter);
  const Eigen::MatrixXd cov = dmap * fit.covariance * dmap.transpose();
  out.covariance = cov;
  for (int k = 0; k < 9; ++k) {
    const bool estimated = dmap.row(k).norm() > 0;
    out.standard_error(k) = estimated ? std::sqrt(std::max(cov(k, k), 0.0)) : NAN;
  }
  const Eigen::VectorXd pred = fit.predicted_std;
  for (int k = 0; k < 9; ++k)
    if (dmap.row(k).norm() > 0) {
      int j = 0;
      dmap.row(k).cwiseAbs().maxCoeff(&j);
      out.predicted_std(k) = pred(j);
    }
  for (const auto& it : items) {
    const Vec3 c = out.meter.compensate(it.mean);
    out.residuals.push_back(c.norm() - it.modulus);
    out.directions.push_back(c.normalized());
  }
  out.item_scale = fit.scale[0];
  out.item_dof = fit.dof[0];
  if (!rests.empty()) out.rest_scale = fit.scale[1], out.rest_dof = fit.dof[1];
  out.condition = fit.rank_condition;
  out.iterations = fit.iterations;
  out.summary = fit.summary;
  return out;
}

std::vector<Vec3> item_directions(const std::vector<ModulusItem>& items, const std::vector<LogInterval>& rests) {
  const Full x = start_of(items, rests);
  std::vector<Vec3> out;
  for (const auto& it : items)
    out.push_back((it.mean - Vec3(x.head<3>())).cwiseQuotient(Vec3(x.segment<3>(3))).normalized());
  return out;
}

namespace {

// A model's design at the items' directions, with the rests' rows when there are rests (they observe
// the three offsets directly, as much as the items together): the rows (x, y, z, x^2, ..., zx) of
// paper9, (x, y, z, x^2, y^2, z^2) of axis6, (x, y, z, 1) of the gyro's bias3 (offsets and one gain).
Eigen::MatrixXd gyro_information(ModelKind model, const std::vector<Vec3>& eta, bool rests) {
  const Layout L = layout_of(model);
  const int P = L.free;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(P, P);
  for (const Vec3& e : eta) {
    Eigen::VectorXd h(P);
    if (!L.gains)
      h << e, 1;
    else
      h = Paper9Model::row(e).head(P);
    M += h * h.transpose();
  }
  if (rests)
    for (int c = 0; c < 3; ++c) M(c, c) += static_cast<double>(eta.size()) / 3;
  return M;
}

}  // namespace

KnownModulusCalibration calibrate_known_moduli_auto(const std::string& file, const std::vector<ModulusItem>& items,
                                                    const std::vector<LogInterval>& rests, std::string& reason) {
  const std::vector<Vec3> eta = item_directions(items, rests);
  const std::string what =
      std::to_string(items.size()) + (rests.empty() ? " segments or turns" : " segments or turns and the rests");
  std::ostringstream why;
  why.precision(3);
  for (const ModelKind model : auto_choice_models()) {
    const std::string_view name = model_name(model);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(gyro_information(model, eta, !rests.empty()),
                                                      Eigen::EigenvaluesOnly);
    const double lo = es.eigenvalues().minCoeff(), hi = es.eigenvalues().maxCoeff();
    const double condition = lo > 1e-12 * hi ? hi / lo : INFINITY;
    if (condition > kCarryCondition) {
      why << (why.tellp() > 0 ? "; " : "") << name << " not (condition " << condition << " > " << kCarryCondition
          << ")";
      continue;
    }
    std::ostringstream r;
    r.precision(3);
    r << "the " << what << " identify " << name << " (condition " << condition << ")";
    if (why.tellp() > 0) r << "; " << why.str();
    reason = r.str();
    KnownModulusOptions o;
    o.model = model;
    return calibrate_known_moduli(file, items, rests, o);
  }
  throw InputError(file, 0, "the " + what + " carry no model: " + why.str());
}

}  // namespace scalcal::gyro
