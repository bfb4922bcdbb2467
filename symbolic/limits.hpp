// The N -> infinity limits derived symbolically: for a measure symmetric under the 48 signed
// permutations of the axes, M/N = diag(I/3, (a-b) I + b J, b I) with a = 1/3 - 2b, and each
// criterion is minimised over b in (0, 1/9) exactly (stationary points and crossings).
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/criteria/registry.hpp"

namespace scalcal::symbolic {

// M/N of the symmetric measure with E[x^2 y^2] = b.
GiNaC::matrix symmetric_moment_matrix(const GiNaC::ex& b);

// The normalised criterion of the symmetric measure as a max of closed forms in b.
std::vector<GiNaC::ex> criterion_pieces(CriterionKind c, const GiNaC::symbol& b);

struct SymbolicLimit {
  GiNaC::ex value;  // infimum of the normalised criterion
  GiNaC::ex b;      // E[x^2 y^2] of the optimal symmetric measure
  GiNaC::ex x4;     // E[x^4] = 1/3 - 2b
};

// min over b in (0, 1/9) of max_i pieces_i(b): the minimiser is a stationary point of one piece
// or a crossing of two, all roots of polynomials of degree <= 2 found in closed form.
SymbolicLimit minimise_max(const std::vector<GiNaC::ex>& pieces, const GiNaC::symbol& b);

// Throws std::invalid_argument("no known limit for criterion X") for a criterion without closed
// forms on the symmetric measures (has_symbolic_limit is false).
SymbolicLimit symbolic_limit(CriterionKind c);
bool has_symbolic_limit(CriterionKind c);

}  // namespace scalcal::symbolic
