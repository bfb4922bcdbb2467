// Which limits a jig reaches, decided exactly from its face normals: a 4-design has the sphere's
// moments up to degree 4 in every orientation (so every criterion is the same however the meter
// sits); D's limit needs a 4-design (proofs/d_equality.md); A's optimum is unique, so a jig whose
// rotation-invariant fourth-moment norm differs from the optimum's never reaches A.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/criteria/registry.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

// E[x^a y^b z^c] over the uniform measure on the unit sphere.
GiNaC::ex sphere_moment(int a, int b, int c);

// True when sum_i w_i m(eta_i) = N E[m] for every monomial m of degree 1..t.
bool is_design(const std::vector<WeightedPoint>& points, int t);

// (1/N^2) sum_ij w_i w_j (eta_i . eta_j)^4: the squared norm of the fourth-moment tensor, the same in
// every orientation.
GiNaC::ex fourth_moment_norm(const std::vector<WeightedPoint>& points);

// The same norm for the symmetric measure with E[x^2 y^2] = b: 1/3 - 4b + 30 b^2.
GiNaC::ex symmetric_fourth_moment_norm(const GiNaC::ex& b);

struct JigLimitClaim {
  std::string status;  // "reached in every orientation", "never reached", "reached at the default mounting",
                       // "not decided exactly"
  bool proven = false;
  std::string reason;
};

struct JigAnalysis {
  bool four_design = false;                          // every criterion is the same in every orientation
  std::optional<ExactCriteria> at_default;           // nullopt when the jig is rank-deficient
  std::array<JigLimitClaim, kCriterionCount> claim;  // by CriterionKind index
};

// `normals` at the default mounting, N >= 1.
JigAnalysis analyse_jig(const std::vector<WeightedPoint>& normals);

}  // namespace scalcal::symbolic
