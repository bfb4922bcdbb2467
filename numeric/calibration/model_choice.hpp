// Which registered model a measured layout can carry, decided from the positions' directions before
// any fit (issue 31): a model is carried when its design H has full rank at those directions and
// H^T H's condition number is at most kCarryCondition. Six faces cannot carry non-orthogonality
// (the cross terms xy, yz, zx vanish there), positions on one great circle leave a quadratic
// combination free, fewer positions than parameters leave the rank short: each is named.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

// sqrt(1e4) = 100: above this the worst-determined combination of parameters is known 100 times
// less well than the best one, and an estimate of it is mostly the data's other errors. Measured on
// the logs of data/: the hand-held Xsens log (38 positions) has condition 323, a magnetometer log
// (15 positions) 753; a 10-position log 4e5 and a six-face (Ferraris) log 5e7 for paper9, and under
// 50 for axis6 on all of them.
inline constexpr double kCarryCondition = 1e4;

struct LayoutVerdict {
  ModelKind model = ModelKind::paper9;
  bool carried = false;
  double condition = 0;
  std::string why;                             // why not (rank or conditioning), empty when carried
  std::vector<std::string> poorly_determined;  // the parameters of the null space or the worst combination
};

// gain_estimated: the field's common gain is fitted too (magnitude auto, or data not in the field's units,
// whose start estimates it): a model whose rows do not span the constant (bias3) is then judged with that
// column added, since a circle of positions trades the offset along its normal against the gain (a planar
// layout of bias3 in counts otherwise passes with offsets of 1e5 counts; the C library found it).
LayoutVerdict judge_layout(ModelKind model, const Program& directions, bool gain_estimated = false);

struct ModelChoice {
  ModelKind model = ModelKind::paper9;
  std::string reason;                         // one sentence: what the layout identifies and what it does not
  std::vector<std::string> not_identifiable;  // parameters of the richest model the layout cannot carry
};

// --model auto: the richest of the linear models (paper9, then axis6, then bias3; cubic12 only when
// asked for: its correction is not linear and it needs the field's strength) that the layout
// carries. Empty when none does (too few positions).
std::optional<ModelChoice> choose_model(const Program& directions, bool gain_estimated = false);

// The positions' directions before any fit: the normalised means when the data are in the field's
// units (within 10 % of magnitude; the nominal directions for the projection modulus), else the
// means through an axis-aligned ellipsoid (which every layout of six or more positions off one plane
// determines). Empty when no such ellipsoid exists.
std::optional<std::vector<Vec3>> layout_directions(const std::vector<PositionSamples>& data, double magnitude,
                                                   bool magnitude_auto, Modulus modulus);
// Whether the gain is fitted with the offsets (judge_layout's gain_estimated): magnitude auto, or the data
// not within 10 % of magnitude (layout_directions' ellipsoid start), the projection modulus never.
bool gain_estimated(const std::vector<PositionSamples>& data, double magnitude, bool magnitude_auto, Modulus modulus);

}  // namespace scalcal
