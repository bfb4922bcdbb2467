// When two calibration programs are the same program: some symmetry of the criterion (a signed
// permutation of the axes for every criterion, any orthogonal map for D) carries the multiset of
// positions of one onto that of the other. The multistart uses it to count distinct optima.
#pragma once
#include <optional>
#include <vector>

#include "numeric/model/paper9.hpp"
#include "numeric/program/program.hpp"
#include "numeric/program/program_symmetry.hpp"

namespace scalcal {

// A g of the group and a one-to-one pairing pi with |g a_i - b_pi(i)| <= tol for every i, or
// nullopt. Every map returned has been checked against that definition, so a wrong "yes" cannot
// happen; under Orthogonal the map is estimated from the data (anchor frames, then a Procrustes
// refit), so a "no" is only guaranteed for programs whose best residual is not close to tol.
// Programs of different sizes are never equivalent; two empty programs are.
// Collinear programs (every pair of positions within angle ~tol of parallel, e.g. copies of +-z)
// leave the twist about their line free: the map sends line to line (both orientations, with and
// without a reflection) with an arbitrary twist, exact up to the positions' sideways residuals.
std::optional<Mat3> equivalence_map(const Program& a, const Program& b, ProgramSymmetry symmetry, double tol = 1e-6);

bool equivalent(const Program& a, const Program& b, ProgramSymmetry symmetry, double tol = 1e-6);

// Class label per program, 0, 1, ... in order of first appearance. Greedy: each program is compared
// with the first member (the representative) of every class so far, so with a tol near the spread
// of a class the result can depend on the order.
std::vector<int> equivalence_classes(const std::vector<Program>& programs, ProgramSymmetry symmetry, double tol = 1e-6);

// The number of classes of equivalence_classes().
int count_distinct(const std::vector<Program>& programs, ProgramSymmetry symmetry, double tol = 1e-6);

}  // namespace scalcal
