// Augmenting a lab's program: greedy and exchange on the region's grid, then the added positions
// optimised jointly inside the zones from several starts (augment_polish.hpp); one body per model
// (the criterion comes in as a CriterionOps).
#include "numeric/region/augment.hpp"

#include <cmath>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/exchange.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {
namespace {

template <class Model>
AugmentedProgram augment_with(const CriterionOps<Model>& criterion, const Program& given, int add, const Region& region,
                              ModelKind model, const AugmentPolishOptions& options) {
  AugmentedProgram out;
  out.value_before = given.size() > 0 ? criterion_value(criterion, given) : INFINITY;
  if (!std::isfinite(out.value_before)) out.value_before = INFINITY;
  // Greedy on the grid (ranked through a ridge while the program is rank-deficient, so that what a
  // candidate makes identifiable decides), then exchanges among the added positions.
  const std::vector<Vec3> candidates = region.grid(region.grid_step_for(kRegionGridCandidates));
  const ExchangeResult ex = greedy_exchange(*criterion.kind, candidates, given.positions, add, model);
  // Then the added positions move jointly inside their zones, the given ones held fixed, from the
  // exchange and from random starts (in worker processes: Ipopt's MUMPS state must not be inherited
  // by later forks).
  const PolishedAddition best = polish_added(
      *criterion.kind, model, region, given.positions, ex, candidates, options,
      [&criterion](const Program& p) { return criterion_value(criterion, p); },
      [&criterion](const Program& start, const PositionBounds& bounds) {
        return ipopt_local<Model>(criterion, start, zone_polish_options(criterion.form == CriterionForm::Smooth),
                                  &bounds);
      });
  out.program = given;
  out.added = best.added;
  out.program.positions.insert(out.program.positions.end(), out.added.begin(), out.added.end());
  out.value = best.value;
  out.starts = best.starts;
  out.best_start = best.best_start;
  out.value_greedy = best.value_greedy;
  return out;
}

}  // namespace

AugmentedProgram augment_program(const Program& given, int add, CriterionKind criterion, const Region& region,
                                 ModelKind model, const AugmentPolishOptions& polish) {
  return visit_model(model, [&](auto M) -> AugmentedProgram {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>) {
      return visit_criterion(criterion, [&](auto C) {
        return augment_with<Model>(criterion_ops<decltype(C), Model>(), given, add, region, model, polish);
      });
    } else {
      throw_no_synthesis(Model::name);
    }
  });
}

}  // namespace scalcal
