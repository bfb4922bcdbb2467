// Which model a layout carries: rank and condition of each model's design at the measured directions.
#include "numeric/calibration/model_choice.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal {

LayoutVerdict judge_layout(ModelKind model, const Program& directions) {
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
  v.carried = true;
  return v;
}

std::optional<ModelChoice> choose_model(const Program& directions) {
  const ModelKind candidates[] = {*parse_model("paper9"), *parse_model("axis6"), *parse_model("bias3")};
  const LayoutVerdict richest = judge_layout(candidates[0], directions);
  std::ostringstream s;
  s << std::setprecision(3);
  for (const ModelKind m : candidates) {
    const LayoutVerdict v = m == candidates[0] ? richest : judge_layout(m, directions);
    if (!v.carried) continue;
    ModelChoice c;
    c.model = m;
    if (m == candidates[0]) {
      s << "the " << directions.size() << " positions identify all " << model_parameters(m)
        << " parameters of paper9 (condition " << v.condition << ")";
    } else {
      s << "the " << directions.size() << " positions cannot carry paper9 (" << richest.why << "); " << model_name(m)
        << " is the richest model they carry (condition " << v.condition << ")";
      // What the chosen model leaves out of paper9 is what the layout could not identify.
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

std::optional<std::vector<Vec3>> layout_directions(const std::vector<PositionSamples>& data, double magnitude,
                                                   bool magnitude_auto, Modulus modulus) {
  std::vector<Vec3> out;
  if (modulus == Modulus::projection) {
    for (const auto& p : data) out.push_back(p.nominal->normalized());
    return out;
  }
  std::vector<double> ratio;
  std::vector<Vec3> means;
  for (const auto& p : data) {
    means.push_back(p.mean());
    ratio.push_back(means.back().norm() / magnitude);
  }
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2), ratio.end());
  if (!magnitude_auto && std::abs(ratio[ratio.size() / 2] - 1) <= 0.1) {
    for (const Vec3& m : means) out.push_back(m.normalized());
    return out;
  }
  const auto start = fit_ellipsoid(means, 1.0, EllipsoidShape::axis_aligned);
  if (!start) return std::nullopt;
  for (const Vec3& m : means) out.push_back(start->apply(m).normalized());
  return out;
}

}  // namespace scalcal
