// Augmenting a lab's program: greedy and exchange on the region's grid, then Ipopt inside the zones;
// one body per model (the criterion comes in as a CriterionOps).
#include "numeric/region/augment.hpp"

#include <cmath>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/exchange.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/synthesis_models.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

template <class Model>
AugmentedProgram augment_with(const CriterionOps<Model>& criterion, const Program& given, int add, const Region& region,
                              ModelKind model) {
  AugmentedProgram out;
  out.value_before = given.size() > 0 ? criterion_value(criterion, given) : INFINITY;
  if (!std::isfinite(out.value_before)) out.value_before = INFINITY;
  // Greedy on the grid (ranked through a ridge while the program is rank-deficient, so that what a
  // candidate makes identifiable decides), then exchanges among the added positions.
  const std::vector<Vec3> candidates = region.grid(region.grid_step_for(kRegionGridCandidates));
  const ExchangeResult ex = greedy_exchange(*criterion.kind, candidates, given.positions, add, model);
  Program best{ex.positions};
  double value = criterion_value(criterion, best);
  // Then the added positions move continuously inside their zones, the given ones held fixed
  // (in a worker process: Ipopt's MUMPS state must not be inherited by later forks).
  if (!region.zones.empty() && std::isfinite(value)) {
    PositionBounds bounds = position_bounds(region, ex.positions);
    for (int i = 0; i < given.size(); ++i) bounds[static_cast<std::size_t>(i)].kind = PositionBound::Kind::Fixed;
    LocalResult polished = run_in_workers(1, 1, best.size(), [&](int) {
      return ipopt_local<Model>(criterion, best, {}, &bounds);
    })[0];
    for (std::size_t i = 0; i < bounds.size(); ++i) {
      Vec3& x = polished.program.positions[i];
      if (bounds[i].kind == PositionBound::Kind::Fixed) x = ex.positions[i];  // bit for bit
      if (bounds[i].kind == PositionBound::Kind::Zone)
        x = clamp_to_zone(region.zones[static_cast<std::size_t>(region.deepest_zone(ex.positions[i]))], x);
    }
    const double v = criterion_value(criterion, polished.program);
    if (v < value) {
      best = polished.program;
      value = v;
    }
  }
  out.program = given;
  out.added.assign(best.positions.begin() + given.size(), best.positions.end());
  out.program.positions.insert(out.program.positions.end(), out.added.begin(), out.added.end());
  out.value = value;
  return out;
}

}  // namespace

AugmentedProgram augment_program(const Program& given, int add, CriterionKind criterion, const Region& region,
                                 ModelKind model) {
  return visit_model(model, [&](auto M) -> AugmentedProgram {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>) {
      return visit_criterion(criterion, [&](auto C) {
        return augment_with<Model>(criterion_ops<decltype(C), Model>(), given, add, region, model);
      });
    } else {
      throw_no_synthesis(Model::name);
    }
  });
}

}  // namespace scalcal
