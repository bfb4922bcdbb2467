// Shared options (common_options.hpp).
#include "commands/core/common_options.hpp"

#include <charconv>
#include <stdexcept>

#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/thermal/temperature_range.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal::commands {

std::vector<std::string> criterion_names() {
  std::vector<std::string> names;
  for (auto c : kCriteria) names.emplace_back(criterion_name(c));
  return names;
}

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (int i = 0; i < kModelCount; ++i) names.emplace_back(model_name(ModelKind(i)));
  return names;
}

std::vector<std::string> local_solver_names() { return {"auto", "newton", "lbfgs", "ipopt"}; }

LogFormat log_format_named(const std::string& name) {
  return name == "text" ? LogFormat::text : name == "csv" ? LogFormat::csv : LogFormat::automatic;
}

std::string shortest_text(double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

std::string criterion_names_text() { return scalcal::criterion_names(", "); }

Option integer_option(std::string name, long long lo, long long hi, std::string what, std::string unit,
                      std::string fallback, std::string fallback_text) {
  Option o;
  o.name = std::move(name);
  o.kind = OptionKind::integer;
  o.lo = lo, o.hi = hi;
  o.what = std::move(what), o.unit = std::move(unit), o.fallback = std::move(fallback);
  o.fallback_text = std::move(fallback_text);
  return o;
}

Option number_option(std::string name, double low, double high, std::string what, std::string unit,
                     std::string fallback) {
  Option o;
  o.name = std::move(name);
  o.kind = OptionKind::number;
  o.low = low, o.high = high;
  o.what = std::move(what), o.unit = std::move(unit), o.fallback = std::move(fallback);
  return o;
}

Option positive_option(std::string name, std::string what, std::string unit, std::string fallback) {
  Option o = number_option(std::move(name), 0, 0, std::move(what), std::move(unit), std::move(fallback));
  o.positive = true;
  return o;
}

Option text_option(std::string name, std::string value_name, std::string what, std::string unit, std::string fallback) {
  Option o;
  o.name = std::move(name);
  o.kind = OptionKind::text;
  o.value_name = std::move(value_name);
  o.what = std::move(what), o.unit = std::move(unit), o.fallback = std::move(fallback);
  return o;
}

Option choice_option(std::string name, std::vector<std::string> choices, std::string what, std::string fallback) {
  Option o;
  o.name = std::move(name);
  o.kind = OptionKind::choice;
  o.choices = std::move(choices);
  o.what = std::move(what), o.fallback = std::move(fallback);
  return o;
}

Option named(Option option, std::string value_name) {
  option.value_name = std::move(value_name);
  return option;
}

Option positions_option(Option option) {
  option.takes_positions = true;
  return option;
}

Option flag_option(std::string name, std::string what) {
  Option o;
  o.name = std::move(name);
  o.kind = OptionKind::flag;
  o.what = std::move(what);
  o.fallback = "0";
  return o;
}

Option criterion_option(const std::string& fallback) {
  // Shown as C in usage lines; --help lists the names with their forms.
  std::string what = "the criterion:";
  for (auto c : kCriteria)
    what += std::string(c.index() ? "," : "") + " " + std::string(criterion_name(c)) + " = " + criterion_label(c, 9);
  Option o = choice_option("--criterion", criterion_names(), what, fallback);
  o.value_name = "C";
  return o;
}

Option model_option() {
  std::string what = "the calibration model:";
  for (int i = 0; i < kModelCount; ++i)
    what += std::string(i ? "," : "") + " " + std::string(model_name(ModelKind(i))) + " (" +
            std::string(visit_model(ModelKind(i), [](auto M) { return decltype(M)::summary; })) + ")";
  Option o = choice_option("--model", model_names(), what, "paper9");
  o.value_name = "NAME";
  return o;
}

Option model_or_thermal_option() {
  Option o = model_option();
  o.what +=
      "; or a thermal model BASE+Tk (every parameter a polynomial of degree k in temperature) or "
      "BASE+bias:Tk (the biases only), k = 1.." +
      std::to_string(kMaxThermalDegree);
  o.kind = OptionKind::text;
  o.choices.clear();
  o.why_bad = [](const std::string& text) -> std::string {
    if (parse_model(text)) return "";
    try {
      if (parse_thermal_model(text)) return "";
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "must be one of " + scalcal::model_names(", ") + ", or BASE+Tk / BASE+bias:Tk (got '" + text + "')";
  };
  return o;
}

Option temperature_option() {
  Option o = text_option(
      "--temperature", "T1..T2",
      "the temperatures a thermal model spans (its polynomials are in tau = (T - middle) / half-range)", "degC");
  o.why_bad = [](const std::string& text) -> std::string {
    try {
      parse_temperature_range(text);
      return "";
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
  };
  return o;
}

Option region_option() {
  Option o = text_option("--region", "SPEC",
                         "directions the bench reaches; repeat for a union: sphere, cap:DEG[:X,Y,Z], "
                         "band:LO:HI[:X,Y,Z], faces:DEG, candidates:FILE",
                         "degrees", "");
  o.kind = OptionKind::repeated;
  o.fallback_text = "sphere";
  return o;
}

Option tolerance_option() {
  return named(number_option("--tolerance", 0, 10,
                             "a position this far outside the region still counts as inside (a bench set to 0.1 "
                             "degrees puts a rim position up to 0.05 beyond it)",
                             "degrees", "0.05"),
               "DEG");
}

Option seed_option() {
  Option o = integer_option("--seed", kSeeds.lo, kSeeds.hi,
                            "seed of every random choice (the same seed, the same answer)", "none", "1");
  o.value_name = "S";
  return o;
}

Option starts_option() {
  Option o =
      integer_option("--starts", kStarts.lo, kStarts.hi, "random starts of the multistart", "starts", "0",
                     words("adaptive: batches of 8 until 8 consecutive starts hit the best, capped at the criterion's "
                           "count; 8 on a restricted {region}; K forces K"));
  o.value_name = "K";
  return o;
}

Option threads_option() {
  Option o = integer_option("--threads", kThreads.lo, kThreads.hi, "worker threads or processes", "threads", "0",
                            "0 = all cores");
  o.value_name = "T";
  return o;
}

Option local_option() {
  return choice_option("--local", local_solver_names(),
                       "local solver: auto = Riemannian Newton for D and A below N = 40, L-BFGS from N = 40, Ipopt "
                       "for E and S (E warm-started by A's solver); newton, lbfgs = that solver for D, A and E's warm "
                       "start; ipopt = Ipopt for all",
                       "auto");
}

Option program_argument(const std::string& what) {
  Option o;
  o.name = "PROGRAM";
  o.kind = OptionKind::positional;
  o.takes_positions = true;
  o.what = what.empty() ? "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)" : what;
  return o;
}

Option json_option(const std::string& what) {
  Option o = flag_option("--json", what);
  o.cli_only = true;
  return o;
}

Option out_option(const std::string& what, const std::string& value_name) {
  Option o = text_option("--out", value_name, what, "file path; - for standard output");
  o.cli_only = true;
  o.writes_file = true;
  return o;
}

CriterionKind criterion_of(const Values& v, const std::string& option) {
  const auto c = parse_criterion(v.text(option));
  if (!c) throw std::logic_error("unchecked criterion '" + v.text(option) + "'");
  return *c;
}

ModelKind model_of(const Values& v) {
  const auto m = parse_model(v.text("--model"));
  if (!m) throw std::logic_error("unchecked model '" + v.text("--model") + "'");
  return *m;
}

LocalSolver local_solver_of(const Values& v) {
  const std::string name = v.text("--local");
  return name == "newton"  ? LocalSolver::Newton
         : name == "lbfgs" ? LocalSolver::Lbfgs
         : name == "ipopt" ? LocalSolver::Ipopt
                           : LocalSolver::Automatic;
}

// The minimum number of positions is the model's (one per parameter), so it is checked here, where
// the model is known, not by the file reader (which only refuses fewer than any model needs).
Program program_of(const Values& v, const std::string& option) {
  Program p = v.program ? *v.program : resolve_program(v.text(option));
  const ModelKind model = v.table().find("--model") ? model_of(v) : ModelKind::paper9;
  const int needed = model_parameters(model);
  if (p.size() < needed)
    throw InputError(v.program ? option : v.text(option), 0,
                     "only " + std::to_string(p.size()) + " positions; model " + std::string(model_name(model)) +
                         " needs at least " + std::to_string(needed) + " (one per parameter)");
  return p;
}

}  // namespace scalcal::commands
