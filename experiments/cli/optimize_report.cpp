#include "experiments/cli/optimize_report.hpp"

#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"

namespace scalcal::cli {

Report optimize_report(const OptimizeRequest& o) {
  const SynthesisOptions& opt = o.synthesis;
  const bool paper9 = opt.model == ModelKind::paper9;
  require_positions("optimize", opt.positions, opt.model);
  if (!paper9 && (!o.regions.empty() || o.digits > 0))
    throw UsageError("optimize: --region and --digits work with the paper9 model only (got --model " +
                     std::string(model_name(opt.model)) + ")");
  const std::optional<Region> region =
      o.regions.empty() ? std::nullopt : std::optional<Region>(resolve_region(o.regions, "optimize"));
  const bool restricted = region && !region->is_sphere();
  if (restricted && o.digits > 0)
    throw InputError("--digits", 0,
                     "the polish solves the unconstrained optimality conditions; it cannot keep "
                     "positions inside --region " +
                         region->text());
  const SynthesisResult r = restricted ? synthesize_on_region(opt, *region) : synthesize(opt);
  if (opt.progress) std::cerr << "\n";
  if (!r.summary.converged())
    std::cerr << "scalcal optimize: warning: " << r.summary.message << " (" << r.local_solver << " multistart)\n";
  std::optional<PolishResult> polished;
  if (o.digits > 0) {
    if (opt.progress) std::cerr << "polishing at " << o.digits << " digits\n";
    polished = polish(r.program, opt.criterion, PolishOptions{o.digits, 40});
    if (!polished->converged())
      std::cerr << "scalcal optimize: warning: the polish did not converge (residual " << polished->residual
                << "); value_digits keeps " << polished->digits << " digits\n";
  }
  // The polished program is the better one (its rounding to double is as close to the optimum as
  // double allows): it is the one written and printed.
  const Program& best = polished ? polished->program : r.program;
  if (!o.out.empty())
    write_program_file(o.out, best, region ? region_columns(*region, best) : std::vector<ExtraColumn>{});
  std::optional<double> limit;
  if (!paper9) {
    if (const auto l = stated_limit(opt.model, criterion_name(opt.criterion))) limit = l->value;
  } else if (region) {
    if (opt.progress) std::cerr << "the " << criterion_name(opt.criterion) << " limit on " << region->text() << "\n";
    limit = limit_value(opt.criterion, *region);
  }
  Report report;
  {
    Json j{{"criterion", std::string(criterion_name(opt.criterion))},
           {"positions", opt.positions},
           {"value", r.value},
           {"program", program_json(best)},
           {"starts", r.starts},
           {"stopping", r.stopping},
           {"hits", r.hits},
           {"distinct", r.distinct},
           {"seconds", r.seconds},
           {"local_solver", r.local_solver},
           {"confirmed", r.summary.converged()}};
    if (!paper9) {
      j["model"] = std::string(model_name(opt.model));
      if (limit) {
        j["limit"] = *limit;
        j["efficiency"] = efficiency(opt.criterion, *limit, r.value, model_parameters(opt.model));
      }
    } else if (limit) {
      j["region"] = region->text();
      j["limit"] = *limit;
      j["efficiency"] = efficiency(opt.criterion, *limit, r.value);
    }
    if (polished) {
      j["value_digits"] = polished->value_digits;
      j["residual"] = polished->residual;
      j["converged"] = polished->converged();
      j["iterations"] = polished->summary.iterations;
    }
    report.json = std::move(j);
  }
  {
    std::ostringstream text;
    text << criterion_name(opt.criterion) << " = " << std::setprecision(15) << r.value << "  (N = " << opt.positions
         << ", " << r.hits << " of " << r.starts << " starts reached it (stopped: " << r.stopping << "), " << r.distinct
         << (r.distinct == 1 ? " program" : " distinct programs") << " up to symmetry, " << std::setprecision(3)
         << r.seconds << " s)\n";
    if (limit && !paper9)
      text << "model " << model_name(opt.model) << ": limit " << std::setprecision(10) << *limit << ", efficiency "
           << std::setprecision(9) << efficiency(opt.criterion, *limit, r.value, model_parameters(opt.model))
           << " (limit / value; D as its " << model_parameters(opt.model) << "th root)\n";
    else if (limit)
      text << "on " << region->text() << ": limit " << std::setprecision(10) << *limit << ", efficiency "
           << std::setprecision(9) << efficiency(opt.criterion, *limit, r.value)
           << " (limit / value; D as its 9th root)\n";
    if (polished)
      text << criterion_name(opt.criterion) << " = " << polished->value_digits << "  (" << polished->digits
           << " digits, residual " << std::setprecision(3) << polished->residual << ", " << polished->summary.iterations
           << " Newton steps)\n";
    report.text = text.str();
  }
  return report;
}

}  // namespace scalcal::cli
