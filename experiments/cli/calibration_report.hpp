// `scalcal calibrate` as functions: the input (samples grouped by position, or a raw log and the
// static intervals found in it) and the scalar calibration with the measured program's quality and
// the positions worth adding. Shared by the CLI and the Python module.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "experiments/cli/options.hpp"
#include "experiments/cli/report.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/io/raw_log.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::cli {

inline constexpr IntegerRange kSuggestions{0, 100};  // positions to suggest adding

struct CalibrationRequest {
  std::string file;                 // the data's name in messages
  std::string magnitude = "auto";   // |I| as the user wrote it (a positive number), or "auto"
  Modulus modulus = Modulus::norm;
  std::string format = "auto";      // of the file: auto, csv or text
  StaticIntervalOptions intervals;  // for a raw log
  std::string weights = "auto";     // auto, samples or positions
  bool keep_outliers = false;
  int suggest = 3;                  // positions to suggest adding
  CriterionKind criterion = CriterionKind::D;
  std::vector<std::string> regions;  // where positions may be added; none: the sphere
  ModelKind model = ModelKind::paper9;
  std::string out;                   // also write the JSON object here (empty: no file)
};

// What the data held: positions, and for a raw log how they were found.
struct CalibrationInput {
  std::vector<PositionSamples> data;
  std::optional<RawLog> log;
  IntervalDetection detection;
};

// Why a --magnitude text is refused ("" when it is a positive number or "auto").
std::string magnitude_problem(const std::string& magnitude);
// UsageError for a bad magnitude or options the model does not take (checked before any file is read).
void check_calibration_request(const CalibrationRequest& request);
// From request.file: grouped samples (strict CSV) or a raw log (CSV or text, by request.format).
CalibrationInput read_calibration_input(const CalibrationRequest& request);
// From a raw log: its static intervals become positions; InputError when fewer than the model's
// parameters are found (the message says what to change), warnings for dropouts and saturation.
CalibrationInput calibration_input(RawLog log, const CalibrationRequest& request);

// Status 1 when the iteration did not converge. Warnings (outliers, poor fit, no noise estimate)
// go to stderr, naming request.file.
Report calibrate_report(const CalibrationRequest& request, CalibrationInput input);

}  // namespace scalcal::cli
