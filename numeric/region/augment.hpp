// Extending the program a lab already has: keep its positions and add the ones, inside the bench's
// region, that improve a criterion most (sequential design). Greedy on a fine candidate grid and
// exchanges among the added positions (numeric/synthesis/exchange.hpp), then the added positions
// are optimised jointly inside their zones with the given ones held fixed, from several starts
// (numeric/region/augment_polish.hpp).
#pragma once
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"
#include "numeric/region/augment_polish.hpp"
#include "numeric/region/region.hpp"

namespace scalcal {

struct AugmentedProgram {
  Program program;  // the given positions, unchanged and first, then the added ones
  std::vector<Vec3> added;
  double value_before = 0;  // the normalised criterion of the given program (infinite if rank < P)
  double value = 0;         // of the augmented program
  double value_greedy = 0;  // from the greedy exchange's start alone (the joint polish's start 0)
  int starts = 0, best_start = 0;
};

// The given program may be rank-deficient (that is often why a lab extends it): candidates are
// then ranked through a tiny ridge, so those that make parameters identifiable win.
AugmentedProgram augment_program(const Program& given, int add, CriterionKind criterion, const Region& region,
                                 ModelKind model = ModelKind::paper9, const AugmentPolishOptions& polish = {});

}  // namespace scalcal
