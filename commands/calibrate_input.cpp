// The data of `calibrate`: bench positions or a raw log's static intervals, and what to say when a
// log has too few of them.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "commands/calibrate.hpp"
#include "commands/usage_error.hpp"
#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

std::string lines_text(const std::vector<int>& lines, int total) {
  std::string s;
  for (int l : lines) s += (s.empty() ? "" : ", ") + std::to_string(l);
  return s + (total > static_cast<int>(lines.size()) ? ", ..." : "");
}

std::string shortest(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Too few intervals: what the detector did, and what would actually help for this log.
std::string too_few_message(const IntervalDetection& d, const StaticIntervalOptions& o, const std::string& need) {
  std::ostringstream s;
  s << std::setprecision(4) << "found " << d.intervals.size() << " static intervals; " << need << ". A window of "
    << d.window << " samples is static when its variance norm stays below " << d.threshold << " = --threshold-factor "
    << o.threshold_factor << " x the noise floor " << d.still_variance << " ("
    << (d.floor_from_still ? "the variance of the first --still " + shortest(o.still_seconds) + " s"
                           : std::string("the median of the log's quiet windows"))
    << "), for at least --min-interval " << o.min_seconds << " s. ";
  if (d.longest_fraction > 0.5) {
    s << "One interval covers " << std::setprecision(2) << 100 * d.longest_fraction
      << " % of the log: the threshold is above the motion"
      << (d.floor_from_still ? "; the --still period is not still (drop --still: the floor then comes from the quiet "
                               "windows)"
                             : "; a smaller --threshold-factor separates the positions");
  } else if (d.short_runs > 0) {
    s << d.short_runs << " still runs were shorter than --min-interval: a shorter --min-interval counts them";
  } else {
    s << "The log holds no other still period of that length: record more positions";
  }
  return s.str();
}

}  // namespace

namespace {

// Bench data or a raw log given as columns (Python): the same checks as a file's.
CalibrationInput input_from_table(const CalibrateRequest& o, const CsvTable& table) {
  if (o.rate > 0 || is_raw_log(table)) {
    if (table.has("position"))
      throw InputError(o.file, 1, "a 'position' column makes this bench data, which --rate does not apply to");
    return calibration_input(raw_log_from_table(table, o.rate), o);
  }
  for (const auto& row : table.rows)
    for (std::size_t c = 0; c < row.values.size(); ++c)
      if (!std::isfinite(row.values[c]))
        throw InputError(o.file, row.line, "value in column " + table.columns[c] + " is not finite");
  CalibrationInput in;
  in.data = measurements_from_table(table, o.modulus == Modulus::projection);
  return in;
}

}  // namespace

CalibrationInput read_calibration_input(const CalibrateRequest& o) {
  if (o.table) return input_from_table(o, *o.table);
  const bool need_nominal = o.modulus == Modulus::projection;
  const std::string text = read_text_file(o.file);
  if (o.format == "text" || (o.format == "auto" && looks_like_text_log(text)))
    return calibration_input(parse_raw_log(text, o.file, LogFormat::text, o.rate), o);
  TableFormat lenient;  // a raw log's dropouts are counted, not refused
  lenient.nonfinite_allowed = true;
  const CsvTable table = parse_table(text, o.file, lenient);
  if (o.rate > 0 || is_raw_log(table)) {
    if (table.has("position"))
      throw InputError(o.file, 1, "a 'position' column makes this bench data, which --rate does not apply to");
    return calibration_input(raw_log_from_table(table, o.rate), o);
  }
  CalibrationInput in;
  in.data = measurements_from_table(parse_csv(text, o.file), need_nominal);  // strict, as always
  return in;
}

CalibrationInput calibration_input(RawLog log, const CalibrateRequest& o) {
  // --model auto takes the richest model the positions carry, down to offsets only.
  const int needed = o.model ? model_parameters(*o.model) : model_parameters(*parse_model("bias3"));
  const std::string need = o.model ? "--model " + std::string(model_name(*o.model)) + " needs at least " +
                                         std::to_string(needed) + " positions"
                                   : "paper9 needs at least 9 positions (axis6 6, bias3 3)";
  CalibrationInput in;
  in.log = std::move(log);
  if (o.modulus == Modulus::projection)
    throw InputError(o.file, 0, "a raw log has no nominal directions: the projection modulus needs them");
  in.detection = detect_static_intervals(*in.log, o.intervals);
  const auto& d = in.detection;
  if (d.nonfinite > 0)
    in.warnings.push_back({o.file, std::to_string(d.nonfinite) +
                                       " rows with a NaN or infinite value are not used (lines " +
                                       lines_text(d.nonfinite_lines, d.nonfinite) + ")"});
  if (d.saturated > 0)
    in.warnings.push_back(
        {o.file, std::to_string(d.saturated) +
                     " samples sit at an output's extreme in runs of three or more (saturated) and are "
                     "not used (lines " +
                     lines_text(d.saturated_lines, d.saturated) + ")"});
  if (d.intervals.size() < static_cast<std::size_t>(needed))
    throw InputError(o.file, 0, too_few_message(d, o.intervals, need));
  for (const auto& iv : d.intervals) {
    PositionSamples p;
    p.line = in.log->lines[static_cast<std::size_t>(iv.begin)];
    for (int i = iv.begin; i <= iv.end; ++i) {
      if (!in.log->finite(i)) continue;
      p.samples.push_back(in.log->samples[static_cast<std::size_t>(i)]);
      p.sample_lines.push_back(in.log->lines[static_cast<std::size_t>(i)]);
    }
    in.data.push_back(std::move(p));
  }
  return in;
}

std::string magnitude_problem(const std::string& s) {
  if (s == "auto") return "";
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v) && v > 0) return "";
  } catch (...) {
  }
  return "must be a positive number or auto, got '" + s + "'";
}

void check_calibrate_request(const CalibrateRequest& o) {
  if (const std::string problem = magnitude_problem(o.magnitude); !problem.empty())
    throw UsageError("calibrate: --magnitude " + problem);
  if (o.model && model_name(*o.model) == "cubic12" && o.magnitude == "auto")
    throw UsageError(
        "calibrate: --magnitude auto does not work with --model cubic12: its cubic term is relative to "
        "|I|, which would be one more unknown; give |I|");
  if (o.model && *o.model != ModelKind::paper9 && !o.regions.empty())
    throw UsageError("calibrate: --region (the advice on what to add) works with the paper9 model only");
  if (!(o.rate >= 0) || !std::isfinite(o.rate)) throw UsageError("calibrate: --rate must be a positive number");
}

}  // namespace scalcal::commands
