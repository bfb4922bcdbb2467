// The Python module `scalcal`: evaluate, optimize, limits and calibrate call the same functions as
// the CLI's subcommands (experiments/cli/*_report.hpp) and return the CLI's JSON object as a dict,
// with arrays of numbers as NumPy arrays. Bad input raises scalcal.InputError or scalcal.UsageError
// (both ValueError) with the CLI's message; the GIL is released while scalcal computes.
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "commands/calibrate.hpp"
#include "commands/calibrate_json.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluate_report.hpp"
#include "experiments/cli/limits_report.hpp"
#include "experiments/cli/optimize_report.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/measurements_csv.hpp"
#include "numeric/program/catalogue.hpp"
#include "python/from_numpy.hpp"
#include "symbolic/family.hpp"
#include "python/to_python.hpp"

namespace py = pybind11;

namespace scalcal::python {
namespace {

// A choice argument, refused with the accepted values (the CLI's check on its --options).
std::string choice(const std::string& argument, const std::string& value, const std::vector<std::string>& choices) {
  for (const auto& c : choices)
    if (value == c) return value;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  throw cli::UsageError(argument + ": '" + value + "' is not one of " + list);
}

// An integer argument within its CLI option's range; `none` (0: the default, no polish) is also taken.
long long in_range(const std::string& argument, long long value, cli::IntegerRange range,
                   std::optional<long long> none = std::nullopt) {
  if (value == none) return value;
  if (value < range.lo || value > range.hi)
    throw cli::UsageError(argument + ": " + std::to_string(value) + " is not in " + std::to_string(range.lo) + ".." +
                          std::to_string(range.hi));
  return value;
}

ModelKind model_of(const std::string& name) { return *parse_model(choice("model", name, cli::model_names())); }

CriterionKind criterion_of(const std::string& name) {
  return *parse_criterion(choice("criterion", name, cli::criterion_names()));
}

// region: None, one spec, or a sequence of specs (their union), as repeated --region options.
std::vector<std::string> regions_of(const py::object& region) {
  if (region.is_none()) return {};
  if (py::isinstance<py::str>(region)) return {region.cast<std::string>()};
  return region.cast<std::vector<std::string>>();
}

// |I| as the CLI reads it: "auto", or a number in its shortest round-trip text.
std::string magnitude_of(const py::object& magnitude) {
  if (py::isinstance<py::str>(magnitude)) return magnitude.cast<std::string>();
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, magnitude.cast<double>()).ptr;
  return std::string(buffer, end);
}

template <class F>
py::object computed(F&& report) {
  cli::Report r;
  {
    py::gil_scoped_release free;
    r = report();
  }
  return to_python(r.json);
}

py::object evaluate(const py::object& positions, const std::string& model, const py::object& region,
                    const std::string& name) {
  cli::EvaluateRequest q;
  q.name = py::isinstance<py::str>(positions) ? positions.cast<std::string>() : name;
  q.program = program_of(positions, name);
  q.model = model_of(model);
  q.regions = regions_of(region);
  return computed([&] { return cli::evaluate_report(q); });
}

py::object optimize(long long n, const std::string& criterion, const std::string& model, const py::object& region,
                    long long starts, long long seed, long long threads, long long digits, const std::string& local) {
  cli::OptimizeRequest q;
  q.synthesis.positions = static_cast<int>(in_range("n", n, cli::kOptimizePositions));
  q.synthesis.criterion = criterion_of(criterion);
  q.synthesis.model = model_of(model);
  q.synthesis.starts = static_cast<int>(in_range("starts", starts, cli::kStarts, 0));
  q.synthesis.seed = static_cast<std::uint64_t>(in_range("seed", seed, cli::kSeeds));
  q.synthesis.threads = static_cast<int>(in_range("threads", threads, cli::kThreads));
  q.synthesis.local = cli::local_solver_of(choice("local", local, cli::local_solver_names()));
  q.digits = static_cast<int>(in_range("digits", digits, cli::kPolishDigits, 0));
  q.regions = regions_of(region);
  return computed([&] { return cli::optimize_report(q); });
}

py::object limits(const std::string& model, const py::object& region) {
  const ModelKind m = model_of(model);
  const std::vector<std::string> regions = regions_of(region);
  return computed([&] { return cli::limits_report(m, regions); });
}

struct IntervalArguments {
  double still, window, threshold_factor, min_interval;
};

py::object calibrate(const py::object& samples, const py::object& magnitude, const py::object& position,
                     const py::object& nominal, const py::object& time, const std::string& modulus,
                     const std::string& weights, bool keep_outliers, long long suggest, const std::string& criterion,
                     const py::object& region, const std::string& model, const IntervalArguments& iv) {
  commands::CalibrateRequest q;
  q.file = "samples";
  q.magnitude = magnitude_of(magnitude);
  q.modulus = choice("modulus", modulus, {"norm", "projection"}) == "norm" ? Modulus::norm : Modulus::projection;
  q.weights = choice("weights", weights, {"auto", "samples", "positions"});
  q.keep_outliers = keep_outliers;
  q.suggest = static_cast<int>(in_range("suggest", suggest, {0, commands::kMaxSuggestions}));
  q.criterion = criterion_of(criterion);
  q.regions = regions_of(region);
  if (model != "auto") q.model = model_of(model);
  for (const auto& [argument, value] : {std::pair{"window", iv.window}, std::pair{"threshold_factor", iv.threshold_factor},
                                        std::pair{"min_interval", iv.min_interval}})
    if (!(value > 0) || !std::isfinite(value))
      throw cli::UsageError(std::string(argument) + ": must be a positive number, got " + std::to_string(value));
  if (!(iv.still >= 0) || !std::isfinite(iv.still))
    throw cli::UsageError("still: must be 0 (the noise floor from the quiet windows) or positive, got " +
                          std::to_string(iv.still));
  q.intervals = {iv.still, iv.window, iv.threshold_factor, iv.min_interval};
  commands::check_calibrate_request(q);

  std::vector<Column> columns = columns_of("samples", samples, {"ix", "iy", "iz"});
  const py::ssize_t rows = columns.front().second.shape(0);
  commands::CalibrationInput input;
  if (!time.is_none()) {
    if (!position.is_none() || !nominal.is_none())
      throw cli::UsageError("time makes samples a raw log, whose positions are its static intervals: give no "
                            "position or nominal with it");
    columns.insert(columns.begin(), column_of("time", time, "t", rows));
    input = commands::calibration_input(raw_log_from_table(table_of(q.file, columns, true)), q);
  } else {
    if (!position.is_none()) columns.push_back(column_of("position", position, "position", rows));
    if (!nominal.is_none())
      for (auto& c : columns_of("nominal", nominal, {"x", "y", "z"})) columns.push_back(std::move(c));
    input.data = measurements_from_table(table_of(q.file, columns, false), q.modulus == Modulus::projection);
  }
  std::optional<commands::CalibrateResult> r;
  {
    py::gil_scoped_release free;
    r = commands::calibrate(q, std::move(input));
  }
  // Warnings reach Python as warnings.warn (UserWarning), as the CLI prints them on stderr.
  for (const auto& w : r->warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, ((w.subject.empty() ? "" : w.subject + ": ") + w.message).c_str(), 1) != 0)
      throw py::error_already_set();
  return to_python(commands::to_json(*r));
}

}  // namespace
}  // namespace scalcal::python

PYBIND11_MODULE(scalcal, m) {
  using namespace scalcal;
  using namespace scalcal::python;
  m.doc() = "scalcal: calibration programs for the scalar calibration of vector meters";
  m.attr("__version__") = SCALCAL_VERSION;
  symbolic::register_family_programs();  // the families' program names, as the CLI has them
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<cli::UsageError> usage_error(m, "UsageError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const cli::UsageError& e) {
      usage_error(e.what());
    }
  });

  m.def(
      "program", [](const std::string& name) { return to_python(cli::program_json(resolve_program(name))); },
      py::arg("name"), "The (N, 3) positions of a catalogue program (see `scalcal catalogue`) or a CSV file.");

  m.def("evaluate", &scalcal::python::evaluate, py::arg("positions"), py::kw_only(), py::arg("model") = "paper9",
        py::arg("region") = py::none(), py::arg("name") = "positions",
        "The criteria D, A, E, S, the RMS errors theta, the program and K of a program: an (N, 3) array of "
        "directions, a catalogue name or a CSV file (`scalcal evaluate --json`). With region (a spec or a list "
        "of specs), also each criterion's efficiency against the region's limit.");

  m.def("optimize", &optimize, py::arg("n"), py::arg("criterion") = "D", py::kw_only(), py::arg("model") = "paper9",
        py::arg("region") = py::none(), py::arg("starts") = 0, py::arg("seed") = 1, py::arg("threads") = 0,
        py::arg("digits") = 0, py::arg("local") = "auto",
        "The optimal program of n positions for a criterion (`scalcal optimize --json`); starts 0 is the "
        "criterion's default, threads 0 all cores, digits > 0 polishes the optimum in MPFR.");

  m.def("limits", &limits, py::kw_only(), py::arg("model") = "paper9", py::arg("region") = py::none(),
        "The N -> infinity limits of the normalised criteria (`scalcal limits --json`): exact on the sphere, "
        "certified bounds on a region.");

  m.def(
      "calibrate",
      [](const py::object& samples, const py::object& magnitude, const py::object& position,
         const py::object& nominal, const py::object& time, const std::string& modulus, const std::string& weights,
         bool keep_outliers, long long suggest, const std::string& criterion, const py::object& region,
         const std::string& model, double still, double window, double threshold_factor, double min_interval) {
        return calibrate(samples, magnitude, position, nominal, time, modulus, weights, keep_outliers, suggest,
                         criterion, region, model, {still, window, threshold_factor, min_interval});
      },
      py::arg("samples"), py::arg("magnitude"), py::kw_only(), py::arg("position") = py::none(),
      py::arg("nominal") = py::none(), py::arg("time") = py::none(), py::arg("modulus") = "norm",
      py::arg("weights") = "auto", py::arg("keep_outliers") = false, py::arg("suggest") = 3,
      py::arg("criterion") = "D", py::arg("region") = py::none(), py::arg("model") = "auto",
      py::arg("still") = StaticIntervalOptions{}.still_seconds, py::arg("window") = StaticIntervalOptions{}.window_seconds,
      py::arg("threshold_factor") = StaticIntervalOptions{}.threshold_factor,
      py::arg("min_interval") = StaticIntervalOptions{}.min_seconds,
      "Scalar calibration (`scalcal calibrate --json`). samples: (M, 3) raw outputs; position: (M,) integer "
      "labels grouping them (none: one position per row); nominal: (M, 3) nominal directions (the projection "
      "modulus needs them); time: (M,) seconds, which makes samples a raw log whose static intervals are the "
      "positions. magnitude: |I| in the samples' units, or 'auto'. model 'auto' fits the richest model the "
      "positions identify; still 0 takes the noise floor from the log's quiet windows.");
}
