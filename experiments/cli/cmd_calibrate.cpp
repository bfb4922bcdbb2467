// `scalcal calibrate --measurements FILE --magnitude M|auto [...]`: the scalar calibration of one
// meter from bench data (samples grouped by position) or from a raw log (time and raw outputs, or
// --rate, the static intervals found in it), in any units, with the model the layout carries
// (commands/calibrate.hpp): options into the request, the result's warnings to stderr, --out, and
// the text or the JSON to stdout. Exit 1 when the fit did not converge.
#include <iostream>
#include <memory>

#include "commands/calibrate.hpp"
#include "commands/calibrate_json.hpp"
#include "experiments/cli/calibrate_text.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage =
    "calibrate --measurements FILE --magnitude M|auto [--model auto|NAME] [--modulus norm|projection] "
    "[--format auto|csv|text] [--rate HZ] [--still S] [--window W] [--threshold-factor K] [--min-interval T] "
    "[--weights auto|samples|positions] [--keep-outliers] [--suggest K] [--criterion C] [--region SPEC]... "
    "[--out FILE] [--json]";

struct Options {
  std::string file, modulus = "norm", magnitude, format = "auto", criterion = "D", out, weights = "auto",
              model = "auto";
  std::vector<std::string> regions;
  StaticIntervalOptions intervals;
  double rate = 0;
  int suggest = 3;
  bool json = false, keep_outliers = false;
};

int run(const Options& o) {
  commands::CalibrateRequest q;
  q.file = o.file;
  q.magnitude = o.magnitude;
  q.modulus = o.modulus == "norm" ? Modulus::norm : Modulus::projection;
  q.format = o.format;
  q.rate = o.rate;
  q.intervals = o.intervals;
  q.weights = o.weights;
  q.keep_outliers = o.keep_outliers;
  q.suggest = o.suggest;
  q.criterion = criterion_of(o.criterion);
  q.regions = o.regions;
  if (o.model != "auto") q.model = model_of(o.model);
  commands::check_calibrate_request(q);
  const commands::CalibrateResult r = commands::calibrate(q);
  print_warnings("calibrate", r.warnings);
  const Json j = commands::to_json(r);
  if (!o.out.empty()) write_output_file(o.out, [&](std::ostream& f) { write_json(f, commands::calibration_file_json(r)); });
  if (o.json) {
    print_json(j);
  } else {
    std::cout << calibrate_text(r);
  }
  return r.status();
}

std::vector<std::string> model_choices() {
  std::vector<std::string> c = {"auto"};
  for (const auto& m : model_names()) c.push_back(m);
  return c;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--measurements", o->file, "FILE",
           {"bench data: CSV with ix,iy,iz [,position] [,x,y,z], or a raw log: CSV with a time column (t, t_s, time, "
            "time_s or timestamp) and ix,iy,iz, or text t ix iy iz",
            "file path", kRequired});
  add_checked_text(app, "--magnitude", o->magnitude, "M|auto",
                   {"modulus |I| of the measured vector, or auto for a field of unknown strength", "physical units",
                    kRequired},
                   commands::magnitude_problem);
  add_choice(app, "--model", o->model, model_choices(),
             {"the calibration model: auto (the richest of paper9, axis6, bias3 that the positions identify), paper9 "
              "(the paper's 9 parameters), axis6 (bias and scale factor), bias3 (offsets only), cubic12 (paper9 plus "
              "x^3, y^3, z^3)"});
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)"});
  add_choice(app, "--format", o->format, {"auto", "csv", "text"},
             {"the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz, no header)"});
  add_number(app, "--rate", o->rate, positive_number(),
             {"the sample rate of a raw log without a time column (or whose time column is the sample index): row k "
              "is at k / HZ seconds; makes a CSV with ix,iy,iz a raw log",
              "Hz"});
  add_number(app, "--still", o->intervals.still_seconds, positive_number(),
             {"take the noise floor from the log's initial still period of this length (default: from the log's "
              "quietest windows, no still start needed)",
              "seconds"});
  add_number(app, "--window", o->intervals.window_seconds, positive_number(),
             {"the moving variance's window in a raw log", "seconds"});
  add_number(app, "--threshold-factor", o->intervals.threshold_factor, positive_number(),
             {"static where the window's variance norm stays below this times the noise floor", "none"});
  add_number(app, "--min-interval", o->intervals.min_seconds, positive_number(),
             {"the shortest static interval that counts as a position", "seconds"});
  add_choice(app, "--weights", o->weights, {"auto", "samples", "positions"},
             {"each position's weight: its number of samples, or 1; auto: positions for a raw log, samples otherwise"});
  add_switch(app, "--keep-outliers", o->keep_outliers,
             "keep samples more than 10 robust scales from their position's median (excluded by default)");
  add_integer(app, "--suggest", o->suggest, 0, commands::kMaxSuggestions,
              {"how many positions to suggest adding (never one twice)", "positions"});
  add_criterion(app, o->criterion, "D");
  add_region_option(app, o->regions);
  add_text(app, "--out", o->out, "FILE",
           {"also write the calibration (the JSON object, with \"converged\") to FILE, for `scalcal correct`",
            "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"calibrate", kUsage,
                        "scalar calibration (eqs. 3-6) in any units, from grouped samples or a raw log, with the model "
                        "the positions identify: bias, scale factors, non-orthogonality with honest standard errors, "
                        "the full correction, each position's residual, the program's quality and what to add",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
