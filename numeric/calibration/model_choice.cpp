// Which model a layout carries: rank and condition of each model's design at the measured directions.
#include "numeric/calibration/model_choice.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal {

namespace {

// With the gain fitted too: the rows and a constant column, unless the rows span the constant already (every
// model with the squares x^2 + y^2 + z^2 = 1); "" when the layout carries it, else why not.
std::string with_gain(ModelKind model, const Program& directions, LayoutVerdict& v) {
  const int P = model_parameters(model), N = directions.size();
  Eigen::MatrixXd H(N, P + 1);
  for (int i = 0; i < N; ++i) {
    const Vec3& eta = directions.positions[static_cast<std::size_t>(i)];
    H.row(i).head(P) = visit_model(model, [&eta](auto M) { return Eigen::VectorXd(decltype(M)::row(eta)); });
    H(i, P) = 1;
  }
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(N);
  const Eigen::VectorXd spanned = H.leftCols(P).colPivHouseholderQr().solve(ones);
  if ((H.leftCols(P) * spanned - ones).norm() <= 1e-9 * std::sqrt(static_cast<double>(N))) return "";
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H.transpose() * H / N);
  const Eigen::VectorXd& l = eig.eigenvalues();
  const double condition = l(0) > 0 ? l(P) / l(0) : INFINITY;
  if (condition <= kCarryCondition) return "";
  v.condition = condition;
  std::ostringstream s;
  s << std::setprecision(3) << "with the gain fitted too (the data are not in the field's units), condition "
    << condition << " > " << kCarryCondition << ": the offset along the positions' common normal trades against "
    << "the gain (positions on one circle; positions off it, or the field's modulus in the data's own units, would "
       "fix it)";
  const ModelEvaluation ev = evaluate(model, directions);
  for (int r = 0; r < P; ++r)
    if (std::abs(eig.eigenvectors()(r, 0)) > 0.3)
      v.poorly_determined.emplace_back(ev.parameter_names[static_cast<std::size_t>(r)]);
  v.poorly_determined.emplace_back("gain");
  return s.str();
}

}  // namespace

LayoutVerdict judge_layout(ModelKind model, const Program& directions, bool gain_estimated) {
  LayoutVerdict v;
  v.model = model;
  const ModelEvaluation ev = evaluate(model, directions);
  v.condition = ev.condition;
  if (!ev.full_rank()) {
    v.why = std::to_string(ev.positions) + " positions, " + rank_deficiency(ev);
    for (int k : ev.unidentifiable) v.poorly_determined.emplace_back(ev.parameter_names[static_cast<std::size_t>(k)]);
    if (v.poorly_determined.empty())
      for (auto name : ev.parameter_names) v.poorly_determined.emplace_back(name);
    return v;
  }
  if (ev.condition > kCarryCondition) {
    std::ostringstream s;
    s << std::setprecision(3) << "condition " << ev.condition << " > " << kCarryCondition
      << ": the combination poorly determined is mostly";
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(ev.information);
    const Eigen::VectorXd worst = eig.eigenvectors().col(0);
    for (int r = 0; r < ev.parameters; ++r)
      if (std::abs(worst(r)) > 0.3) {
        s << (v.poorly_determined.empty() ? " " : ", ") << ev.parameter_names[static_cast<std::size_t>(r)];
        v.poorly_determined.emplace_back(ev.parameter_names[static_cast<std::size_t>(r)]);
      }
    v.why = s.str();
    return v;
  }
  if (gain_estimated) {
    v.why = with_gain(model, directions, v);
    if (!v.why.empty()) return v;
  }
  v.carried = true;
  return v;
}

std::optional<ModelChoice> choose_model(const Program& directions, bool gain_estimated) {
  const std::vector<ModelKind> candidates = auto_choice_models();
  const LayoutVerdict richest = judge_layout(candidates[0], directions, gain_estimated);
  std::ostringstream s;
  s << std::setprecision(3);
  for (const ModelKind m : candidates) {
    const LayoutVerdict v = m == candidates[0] ? richest : judge_layout(m, directions, gain_estimated);
    if (!v.carried) continue;
    ModelChoice c;
    c.model = m;
    if (m == candidates[0]) {
      s << "the " << directions.size() << " positions identify all " << model_parameters(m) << " parameters of "
        << model_name(m) << " (condition " << v.condition << ")";
    } else {
      s << "the " << directions.size() << " positions cannot carry " << model_name(candidates[0]) << " (" << richest.why
        << "); " << model_name(m) << " is the richest model they carry (condition " << v.condition << ")";
      // What the chosen model leaves out of the richest is what the layout could not identify.
      const int P = model_parameters(m);
      const ModelEvaluation full = evaluate(candidates[0], directions);
      for (int k = P; k < full.parameters; ++k)
        c.not_identifiable.emplace_back(full.parameter_names[static_cast<std::size_t>(k)]);
    }
    c.reason = s.str();
    return c;
  }
  return std::nullopt;
}

bool gain_estimated(const std::vector<PositionSamples>& data, double magnitude, bool magnitude_auto, Modulus modulus) {
  if (modulus == Modulus::projection || data.empty()) return false;
  if (magnitude_auto) return true;
  std::vector<double> ratio;
  for (const auto& p : data) ratio.push_back(p.mean().norm() / magnitude);
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2), ratio.end());
  return std::abs(ratio[ratio.size() / 2] - 1) > 0.1;
}

std::optional<std::vector<Vec3>> layout_directions(const std::vector<PositionSamples>& data, double magnitude,
                                                   bool magnitude_auto, Modulus modulus) {
  std::vector<Vec3> out;
  if (modulus == Modulus::projection) {
    for (const auto& p : data) out.push_back(p.nominal->normalized());
    return out;
  }
  std::vector<Vec3> means;
  for (const auto& p : data) means.push_back(p.mean());
  if (!gain_estimated(data, magnitude, magnitude_auto, modulus)) {  // the data are in the field's units
    for (const Vec3& m : means) out.push_back(m.normalized());
    return out;
  }
  const auto start = fit_ellipsoid(means, 1.0, EllipsoidShape::axis_aligned);
  if (!start) return std::nullopt;
  for (const Vec3& m : means) out.push_back(start->apply(m).normalized());
  return out;
}

}  // namespace scalcal
