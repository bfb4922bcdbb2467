// What a measured program is worth and what to add to it: its criteria and RMS errors, its
// efficiency against the limit of the bench's region (the sphere's by default), and the K
// positions that would improve a criterion most (augment), with the criterion after each. Used by
// `calibrate` on the positions a log's static intervals turned out to be.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/region.hpp"

namespace scalcal {

struct SuggestedPosition {
  Vec3 position;
  double value = 0;  // the normalised criterion of the program with this and every earlier suggestion added
  // Its RMS errors per unit noise, sqrt(max K(r,r)) over each group, not normalised by N: what the
  // user's standard errors become (normalised criteria can grow when a near-optimal program grows).
  std::array<double, 3> errors{};
};

// sqrt(max K(r,r)) over bias, scale and non-orthogonality: theta / sqrt(N).
std::array<double, 3> rms_errors(const Evaluation& ev);

struct ProgramAdvice {
  Evaluation evaluation;  // of the measured program
  std::array<double, kCriteria.size()>
      efficiency{};  // per registered criterion: limit / value, D as 9th root; NaN without a known limit
  CriterionKind criterion = CriterionKind::D;  // what the suggestions improve
  std::vector<SuggestedPosition> suggested;
};

// Throws nothing for a rank-deficient program: its efficiencies are 0 and the suggestions repair it.
ProgramAdvice advise_program(const Program& measured, const Region& region, CriterionKind criterion, int suggest);

}  // namespace scalcal
