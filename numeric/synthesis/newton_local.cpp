// Riemannian Newton as a local solver of the multistart, for the criteria that are smooth
// functions of M (D, A); E and S are nonsmooth at their optima and stay with Ipopt.
#include <cmath>

#include "numeric/synthesis/sphere_newton.hpp"
#include "numeric/synthesis/ipopt_local.hpp"

namespace scalcal {

bool newton_applies(CriterionKind criterion) { return criterion == CriterionKind::D || criterion == CriterionKind::A; }

namespace {

template <class Criterion>
LocalResult run_newton(const Program& start, CriterionKind criterion) {
  LocalResult out;
  out.program = start;
  out.value = criterion_value(start, criterion);
  if (!std::isfinite(out.value)) return out;  // rank < 9: no Newton model
  Program moved = start;
  const SphereNewtonResult r = SphereNewton<Criterion>().run(moved.positions);
  out.converged = r.converged;
  out.status = r.converged ? 0 : 1;
  out.iterations = r.iterations;
  const double value = criterion_value(moved, criterion);
  if (std::isfinite(value) && value <= out.value) {
    out.program = std::move(moved);
    out.value = value;
  }
  return out;
}

}  // namespace

LocalResult optimize_by_newton(const Program& start, CriterionKind criterion) {
  switch (criterion) {
    case CriterionKind::D: return run_newton<LogDetCriterion>(start, criterion);
    case CriterionKind::A: return run_newton<TraceCriterion>(start, criterion);
    default: return optimize_locally(start, criterion);
  }
}

}  // namespace scalcal
