// `scalcal calibrate --measurements FILE --magnitude M|auto [...]`: the scalar calibration of one
// meter from bench data (samples grouped by position) or from a raw log (time and raw outputs, the
// static intervals found in it), in any units, with the quality of the program measured and the
// positions worth adding (numeric/calibration/any_units.hpp, numeric/region/program_advice.hpp).
#include <memory>

#include "experiments/cli/calibration_report.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage =
    "calibrate --measurements FILE --magnitude M|auto [--modulus norm|projection] [--format auto|csv|text] "
    "[--still S] [--window W] [--threshold-factor K] [--min-interval T] [--weights auto|samples|positions] "
    "[--keep-outliers] [--suggest K] "
    "[--criterion C] [--region SPEC]... [--model NAME] [--out FILE] [--json]";

struct Options {
  std::string file, modulus = "norm", magnitude, format = "auto", criterion = "D", out, weights = "auto",
              model = "paper9";
  std::vector<std::string> regions;
  StaticIntervalOptions intervals;
  int suggest = 3;
  bool json = false, keep_outliers = false;
};

int run(const Options& o) {
  CalibrationRequest q;
  q.file = o.file;
  q.magnitude = o.magnitude;
  q.modulus = o.modulus == "norm" ? Modulus::norm : Modulus::projection;
  q.format = o.format;
  q.intervals = o.intervals;
  q.weights = o.weights;
  q.keep_outliers = o.keep_outliers;
  q.suggest = o.suggest;
  q.criterion = criterion_of(o.criterion);
  q.regions = o.regions;
  q.model = model_of(o.model);
  q.out = o.out;
  check_calibration_request(q);
  return print_report(calibrate_report(q, read_calibration_input(q)), o.json);
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--measurements", o->file, "FILE",
           {"bench data: CSV with ix,iy,iz [,position] [,x,y,z], or a raw log: CSV with t,ix,iy,iz or text t ix iy iz",
            "file path", kRequired});
  add_checked_text(app, "--magnitude", o->magnitude, "M|auto",
                   {"modulus |I| of the measured vector, or auto for a field of unknown strength", "physical units",
                    kRequired},
                   magnitude_problem);
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)"});
  add_choice(app, "--format", o->format, {"auto", "csv", "text"},
             {"the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz, no header)"});
  add_number(app, "--still", o->intervals.still_seconds, positive_number(),
             {"a raw log's initial still period, whose noise sets the static threshold", "seconds"});
  add_number(app, "--window", o->intervals.window_seconds, positive_number(),
             {"the moving variance's window in a raw log", "seconds"});
  add_number(app, "--threshold-factor", o->intervals.threshold_factor, positive_number(),
             {"static where the window's variance norm stays below this times the still period's", "none"});
  add_number(app, "--min-interval", o->intervals.min_seconds, positive_number(),
             {"the shortest static interval that counts as a position", "seconds"});
  add_choice(app, "--weights", o->weights, {"auto", "samples", "positions"},
             {"each position's weight: its number of samples, or 1; auto: positions for a raw log, samples otherwise"});
  add_switch(app, "--keep-outliers", o->keep_outliers,
             "keep samples more than 10 robust scales from their position's median (excluded by default)");
  add_integer(app, "--suggest", o->suggest, kSuggestions.lo, kSuggestions.hi, {"how many positions to suggest adding", "positions"});
  add_criterion(app, o->criterion, "D");
  add_region_option(app, o->regions);
  add_model(app, o->model);
  add_text(app, "--out", o->out, "FILE", {"also write the JSON object to FILE (for `scalcal correct`)", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"calibrate", kUsage,
                        "scalar calibration (eqs. 3-6) in any units, from grouped samples or a raw log: bias, scale "
                        "factors, non-orthogonality with standard errors, the full correction, the program's quality "
                        "and what to add",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
