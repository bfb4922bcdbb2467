// The multistart for one criterion and model: start k is the uniform random program of seed
// start_seed(seed, k) (for a registered model other than the paper's and a smooth criterion, every
// second one exchanged onto a grid first; for S under a model that states its optimal measure, start 0 from
// N = 48 is that measure rounded, run alone first), optimised by the local solver the criterion's form calls for, in
// threads (Newton, L-BFGS) or worker processes (Ipopt); the best program (lowest value, then lowest start index) never
// depends on scheduling. synthesize_with<Model> is compiled once per model (the criterion is a CriterionOps), in the
// model's synthesis unit; synthesize<C, Model> is its name for one criterion type.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "numeric/criteria/starts.hpp"
#include "numeric/program/program_equivalence.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/exchange_start.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/max_diagonal_newton.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/newton_local.hpp"
#include "numeric/synthesis/rounded_start.hpp"
#include "numeric/synthesis/seeds.hpp"
#include "numeric/synthesis/smooth_optimum_check.hpp"
#include "numeric/synthesis/stopping_rule.hpp"
#include "numeric/synthesis/synthesis_models.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {

// Positions of two runs that reach the same optimum agree to about 1e-7 (Newton, Ipopt on D and
// A) or 1e-5 (Ipopt on the nonsmooth E and S); distinct optima seen so far differ by 1e-2 or more.
inline constexpr double kSameProgramTolerance = 1e-4;

// What runs the starts of a criterion at `positions`: "newton", "lbfgs" or "ipopt".
template <class Model>
LocalSolver starts_solver(const CriterionOps<Model>& criterion, LocalSolver requested, int positions) {
  return criterion.form == CriterionForm::Smooth ? smooth_local_solver(requested, positions) : LocalSolver::Ipopt;
}

inline const char* solver_name(LocalSolver solver) {
  return solver == LocalSolver::Newton ? "newton" : solver == LocalSolver::Lbfgs ? "lbfgs" : "ipopt";
}

// One local optimisation from `start` by the solver the criterion's form calls for.
template <class Model>
LocalResult local_start(const CriterionOps<Model>& criterion, const Program& start, LocalSolver solver) {
  if (criterion.form == CriterionForm::Smooth) {
    const LocalSolver s = smooth_local_solver(solver, start.size());
    if (s == LocalSolver::Ipopt) return ipopt_local<Model>(criterion, start);
    return sphere_local<Model>(criterion, start, s);
  }
  if (criterion.form == CriterionForm::MaxDiagonal && kModelIndex < Model >> 0) {
    // The other models' S optima merge positions onto the axes, which Newton from a random program
    // cannot do without the exchange (see start_at); their S starts stay random, as documented in
    // experiments/docs/sweep.md. (Tried from N = 48 on: starts exchanged for A, D or S, or their A or
    // D optima, were consistent and fast but ended above the random starts' best, cubic12's S at
    // N = 132 at 28.3, 27.225 or 27.09 against 27.08; E from the A optimum of an A-exchanged program
    // reached axis6's limit at N = 150 in 0.4 instead of 81 s but cubic12's E at 39.116 against 39.082.
    // The model's optimal measure rounded to N does better where the model states one: rounded_start.)
    return ipopt_local<Model>(criterion, start);
  }
  // The nonsmooth forms converge poorly from a random program (E at N = 9: random starts ended
  // near 68.7 where the A optimum alone has E = 12.9; S at N = 18: 44-111 Ipopt iterations, from
  // the A optimum 10-14), so the smooth trace criterion runs first, by Newton or L-BFGS, and its
  // program is kept when the E or S stage does not improve on it. For S this took a start from
  // 50 to 8 ms at N = 18 and found the same optima at N = 9..16 with more hits (N = 12: 63 of 64
  // starts, so 8 starts end the run instead of 24).
  const LocalResult warm = local_start<Model>(criterion_ops<ACriterion, Model>(), start, solver);
  LocalResult out = ipopt_local<Model>(criterion, warm.program);
  const double warm_value = criterion_value(criterion, warm.program);
  if (!(out.value <= warm_value)) {
    out.program = warm.program;
    out.value = warm_value;
  }
  out.summary.iterations += warm.summary.iterations;
  return out;
}

// The best of the starts with its summary: the lowest start index among those within kTieTolerance
// of the lowest value. Starts that reach one optimum (often its copies under the criterion's
// symmetry) agree to the solver's accuracy, and which of them is lowest in the last bits turns on the
// BLAS kernel and the CPU (OpenBLAS's Haswell and SkylakeX kernels chose different ones of 7
// equivalent programs); the lowest index does not. A start lower by more than that is better
// converged and wins (E at N = 9: 13 copies of one optimum within 3e-11 of each other, and one 7e-10
// below them, the best converged).
inline constexpr double kTieTolerance = 1e-11;
inline SynthesisResult best_of_starts(const std::vector<LocalResult>& results) {
  double lowest = results[0].value;
  for (const auto& r : results)
    if (r.value < lowest) lowest = r.value;
  std::size_t best = 0;
  while (best + 1 < results.size() && !(results[best].value <= lowest + kTieTolerance * std::abs(lowest))) ++best;
  SynthesisResult out;
  out.program = results[best].program;
  out.value = results[best].value;
  out.summary = results[best].summary;
  return out;
}

// How many starts reached out.value, and how many different programs those are up to the
// criterion's symmetry.
inline void count_hits(const std::vector<LocalResult>& results, ProgramSymmetry symmetry, SynthesisResult& out) {
  std::vector<Program> optima;
  for (const auto& r : results)
    if (r.value <= out.value * (1 + kHitTolerance)) optima.push_back(r.program);
  out.hits = static_cast<int>(optima.size());
  out.distinct = count_distinct(optima, symmetry, kSameProgramTolerance);
}

// The best Newton or L-BFGS program is confirmed in double (smooth_optimum_check.hpp): a Riemannian
// gradient below tolerance and a Hessian positive semidefinite to a margin. Where that check does not
// pass, Ipopt from that program must find it a KKT point with the same value, as before the check
// existed (in a worker process); should it find a lower one, that is kept.
template <class Model>
void confirm_best(const CriterionOps<Model>& criterion, int positions, SynthesisResult& out) {
  const SmoothOptimumCheck check = check_smooth_optimum<Model>(criterion, out.program);
  if (check.passed()) {
    char text[160];
    std::snprintf(text, sizeof text,
                  " program is a local minimum (Riemannian gradient %.1e, Hessian + %.0e of its "
                  "scale positive definite; checked in double)",
                  check.gradient_norm, check.margin);
    out.summary.termination = Termination::converged;
    out.summary.message = std::string("the best ") + out.local_solver + text;
    return;
  }
  const Program best_program = out.program;
  const LocalResult ipopt =
      run_in_workers(1, 1, positions, [&](int) { return ipopt_local<Model>(criterion, best_program); })[0];
  const bool confirmed = ipopt.summary.converged() && ipopt.value <= out.value * (1 + kHitTolerance);
  out.summary.termination = confirmed ? Termination::converged : Termination::not_converged;
  out.summary.message =
      confirmed ? std::string("Ipopt confirmed the best ") + out.local_solver + " program as a KKT point"
                : std::string("Ipopt did not confirm the best ") + out.local_solver + " program as a converged optimum";
  out.summary.iterations = ipopt.summary.iterations;
  if (ipopt.value < out.value) {
    out.program = ipopt.program;
    out.value = ipopt.value;
  }
}

// A start this close to the model's proven limit ends the run by itself (no program can be better by
// more): the rounded optimal measure's polish (rounded_start.hpp) usually is.
inline constexpr double kNearLimit = 1e-3;

// The most starts where they are randomised roundings (ModelLimit::rounding_starts), unless --starts says
// otherwise: their optima come from few roundings (cubic12's S at N = 150: the best of 40 was 27.03683,
// of 170 27.03539, 5e-5 lower, in 55 s instead of 17 s).
inline constexpr int kRoundingStarts = 64;
inline constexpr int kRoundingIterations = 60;

// The rounded optimal measure as start 0 of a max-diagonal criterion under a model other than the paper's
// that states one, from the lifted form's N (random starts there end at distinct optima, each far
// above it; the documented sweeps below that N keep their random starts), or at every N where the model
// asks for randomised roundings (cubic12's S at N = 20, 36, 47: 28.125, 27.246, 27.163 against the
// random starts' 29.387, 28.560, 28.840), unless --from gives start 0.
template <class Model>
std::optional<Program> rounded_start(const CriterionOps<Model>& criterion, const SynthesisOptions& options) {
  if (kModelIndex<Model> <= 0 || criterion.form != CriterionForm::MaxDiagonal || !criterion.kind || options.first_start)
    return std::nullopt;
  const ModelKind model(kModelIndex<Model>);
  const std::string_view name = criterion_name(*criterion.kind);
  if (options.positions < kLiftedFromPositions && !asks_for_rounding_starts(model, name)) return std::nullopt;
  return rounded_limit_measure(model, name, options.positions);
}

// Whether the starts call Ipopt (then they run in worker processes, else in threads).
template <class Model>
bool starts_need_ipopt(const CriterionOps<Model>& criterion, LocalSolver requested, int positions) {
  return starts_solver<Model>(criterion, requested, positions) == LocalSolver::Ipopt;
}

template <class Model>
void check_synthesis_options(const SynthesisOptions& options) {
  if (options.positions < Model::kParameters)
    throw std::invalid_argument("synthesize: at least " + std::to_string(Model::kParameters) + " positions are needed");
  if (options.starts < 0) throw std::invalid_argument("synthesize: the number of starts must not be negative");
  if (options.first_start && options.first_start->size() != options.positions)
    throw std::invalid_argument("synthesize: the first start has " + std::to_string(options.first_start->size()) +
                                " positions, not " + std::to_string(options.positions));
}

// A model other than the paper's states its proven limit (the paper's runs keep their documented
// counts): no start can go below it, so one that reaches it ends the run.
template <class Model>
std::optional<double> stated_proven_limit(const CriterionOps<Model>& criterion) {
  std::optional<double> proven_limit;
  if (kModelIndex < Model >> 0 && criterion.kind)
    if (const auto l = stated_limit(ModelKind(kModelIndex<Model>), criterion_name(*criterion.kind)))
      proven_limit = l->value;
  return proven_limit;
}

// The best start's last steps: confirmed by the Newton solver it came from, or Ipopt's verdict said;
// a max-diagonal criterion's active conditions solved to rounding below the lifted form's N.
template <class Model>
void finish_best(const CriterionOps<Model>& criterion, const SynthesisOptions& options, SynthesisResult& out) {
  const LocalSolver solver = starts_solver<Model>(criterion, options.local, options.positions);
  out.local_solver = solver_name(solver);
  if (solver != LocalSolver::Ipopt) {
    confirm_best<Model>(criterion, options.positions, out);
  } else {
    out.summary.message =
        out.summary.converged() ? "the best Ipopt start converged" : "the best Ipopt start did not converge";
  }
  if (criterion.form == CriterionForm::MaxDiagonal && options.positions < kLiftedFromPositions) {
    // Ipopt's tolerance leaves S about 1e-12 above its optimum; Newton on the active conditions
    // takes it to rounding (a dense step: from the lifted form's N on, Ipopt's value stands).
    const LocalResult refined =
        refine_active_diagonal<Model>(criterion, LocalResult{out.program, out.value, out.summary});
    if (refined.value < out.value) {
      out.program = refined.program;
      out.value = refined.value;
      out.summary.message += "; Newton on its active conditions refined it";
    }
  }
}

// The starts of one multistart. Start k is a function of k alone (its seed, or the rounded measure or
// --from program at k = 0), so any process can run any of them: the synthesis itself, or another MPI
// rank ahead of it, whose results come back as SynthesisOptions::known_starts.
template <class Model>
struct MultistartStarts {
  const CriterionOps<Model>& criterion;
  const SynthesisOptions& options;
  // --starts forces a count; otherwise the criterion's default is a cap and the stopping rule may
  // end the run sooner.
  bool forced = false;
  std::optional<Program> rounded;
  bool rounding_starts = false;
  int cap = 0;
  // Ipopt from a rounding converged in 12-39 iterations (cubic12's S at N = 49, 61, 100, 150); the rare
  // start that wanders (2 of 40 at N = 150, 300 iterations, 11 s each, ending at 27.31 and 66.3) is
  // abandoned sooner.
  LocalOptions rounding_polish;

  MultistartStarts(const CriterionOps<Model>& c, const SynthesisOptions& o)
      : criterion(c), options(o), forced(o.starts > 0), rounded(rounded_start<Model>(c, o)) {
    rounding_starts = rounded && asks_for_rounding_starts(ModelKind(kModelIndex<Model>), criterion_name(*c.kind));
    cap = forced            ? o.starts
          : rounding_starts ? std::min(kRoundingStarts, c.default_starts(o.positions))
                            : c.default_starts(o.positions);
    rounding_polish.max_iterations = kRoundingIterations;
  }

  // The size of the first batch (no batch ends the run before the criterion's minimum number of starts,
  // so the starts up to it run as one batch: the same starts and results, without a wait for the slowest
  // start of every batch of 8 and two forks each; E at N = 9: 256 starts, 32 batches).
  int batch_at(int offset) const {
    if (forced) return cap;
    const int batch = std::min(StoppingRule{}.batch, cap - offset);
    return std::max(batch, std::min(cap, criterion.minimum_starts(options.positions)) - offset);
  }

  // How many starts every run of these options makes, whatever their results: the first batch, unless the
  // rounded measure runs alone first and may end the run by itself (then none is certain).
  int certain() const { return rounded && !forced ? 0 : batch_at(0); }

  LocalResult operator()(int k) const {
    if (k == 0 && options.first_start) return local_start<Model>(criterion, *options.first_start, options.local);
    if (k == 0 && rounded) return local_start<Model>(criterion, *rounded, options.local);
    // A model that asks for them (ModelLimit::rounding_starts) starts again from randomised roundings of
    // its optimal measure.
    if (rounding_starts && k > 0)
      if (const auto variant =
              randomised_rounding(ModelKind(kModelIndex<Model>), criterion_name(*criterion.kind), options.positions,
                                  start_seed(options.seed, static_cast<std::uint64_t>(k))))
        return ipopt_local<Model>(criterion, *variant, rounding_polish);
    Program start = Program::random(options.positions, start_seed(options.seed, static_cast<std::uint64_t>(k)));
    // The paper's model keeps its random starts (its results are documented); every other
    // registered model exchanges every second start onto a grid first (exchange_start.hpp) for
    // the smooth criteria, whose Newton steps cannot merge positions. E and S run Ipopt, which
    // reached every limit at N = 6k for axis6 from random starts, and whose exchange would cost
    // an eigen-decomposition per trial swap (E at N = 24: 33 s of CPU instead of 2 s).
    if (kModelIndex < Model >> 0 && criterion.form == CriterionForm::Smooth && criterion.kind && k % 2 == 1)
      start = exchanged_start(*criterion.kind, ModelKind(kModelIndex<Model>), start);
    return local_start<Model>(criterion, start, options.local);
  }

  // Starts first .. first + count - 1: those options.known_starts holds are taken from it, the others run
  // in worker processes (the starts call Ipopt) or threads; progress counts from `first`.
  std::vector<LocalResult> run(int first, int count, const std::function<void(int, int)>& progress) const {
    const int held = std::clamp(static_cast<int>(options.known_starts.size()) - first, 0, count);
    std::vector<LocalResult> out(options.known_starts.begin() + first, options.known_starts.begin() + first + held);
    if (held == count) return out;
    std::function<void(int, int)> shifted;
    if (progress) shifted = [&](int done, int) { progress(first + held + done, cap); };
    const auto task = [&](int k) { return (*this)(first + held + k); };
    const int workers = thread_count(options.threads);
    const std::vector<LocalResult> done = starts_need_ipopt<Model>(criterion, options.local, options.positions)
                                              ? run_in_workers(count - held, workers, options.positions, task, shifted)
                                              : run_in_threads(count - held, workers, task, shifted);
    out.insert(out.end(), done.begin(), done.end());
    return out;
  }
};

// Starts first .. first + count - 1 of the multistart of these options, as synthesize_with would run them
// (compiled once per model).
template <class Model>
std::vector<LocalResult> multistart_starts_with(const CriterionOps<Model>& criterion, const SynthesisOptions& options,
                                                int first, int count) {
  check_synthesis_options<Model>(options);
  return MultistartStarts<Model>(criterion, options).run(first, count, {});
}

template <class Model>
int certain_starts_with(const CriterionOps<Model>& criterion, const SynthesisOptions& options) {
  check_synthesis_options<Model>(options);
  return MultistartStarts<Model>(criterion, options).certain();
}

// The multistart of one criterion under the model (compiled once per model).
template <class Model>
SynthesisResult synthesize_with(const CriterionOps<Model>& criterion, const SynthesisOptions& options) {
  check_synthesis_options<Model>(options);
  const auto t0 = std::chrono::steady_clock::now();
  const MultistartStarts<Model> starts(criterion, options);
  const int cap = starts.cap;
  const bool forced = starts.forced;
  const StoppingRule rule;
  std::function<void(int, int)> progress;
  if (options.progress) progress = [&](int done, int) { options.progress(done, cap); };
  std::vector<LocalResult> results;
  std::string stopping = forced ? "forced " + std::to_string(cap) : "cap " + std::to_string(cap);
  const std::optional<double> proven_limit = stated_proven_limit<Model>(criterion);
  bool near_limit = false;
  if (starts.rounded && !forced) {
    // The rounded start alone first: within kNearLimit of the proven limit, it ends the run.
    results = run_in_workers(
        1, 1, options.positions, [&](int) { return starts(0); }, progress);
    if (proven_limit && results[0].value <= *proven_limit * (1 + kNearLimit)) {
      near_limit = true;
      char text[120];
      std::snprintf(text, sizeof text, "the rounded optimal measure is within %.2g %% of the proven limit",
                    100 * (results[0].value / *proven_limit - 1));
      stopping = text;
    }
  }
  while (!near_limit && static_cast<int>(results.size()) < cap) {
    const int offset = static_cast<int>(results.size());
    const std::vector<LocalResult> done = starts.run(offset, starts.batch_at(offset), progress);
    results.insert(results.end(), done.begin(), done.end());
    const bool enough = static_cast<int>(results.size()) >= criterion.minimum_starts(options.positions);
    if (!forced && proven_limit && enough && static_cast<int>(results.size()) < cap &&
        best_of_starts(results).value <= *proven_limit * (1 + kHitTolerance)) {
      stopping = "a start reached the proven limit";
      break;
    }
    if (!forced && static_cast<int>(results.size()) < cap && enough && rule.satisfied(results)) {
      stopping = rule.description();
      break;
    }
  }
  const int starts_run = static_cast<int>(results.size());
  SynthesisResult out = best_of_starts(results);
  out.starts = starts_run;
  out.stopping = stopping;
  finish_best<Model>(criterion, options, out);
  count_hits(results, criterion.symmetry, out);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

template <Criterion C, class Model = Paper9Model>
SynthesisResult synthesize(const SynthesisOptions& options) {
  return synthesize_with<Model>(criterion_ops<C, Model>(), options);
}

#define SCALCAL_SYNTHESIZE_INSTANCES(prefix, M)                                                                       \
  prefix template LocalResult local_start<M>(const CriterionOps<M>&, const Program&, LocalSolver);                    \
  prefix template SynthesisResult synthesize_with<M>(const CriterionOps<M>&, const SynthesisOptions&);                \
  prefix template std::vector<LocalResult> multistart_starts_with<M>(const CriterionOps<M>&, const SynthesisOptions&, \
                                                                     int, int);                                       \
  prefix template int certain_starts_with<M>(const CriterionOps<M>&, const SynthesisOptions&);
#define SCALCAL_EXTERN_SYNTHESIZE(M) SCALCAL_SYNTHESIZE_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_SYNTHESIZE)
#undef SCALCAL_EXTERN_SYNTHESIZE

}  // namespace scalcal
