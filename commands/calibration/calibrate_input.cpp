// The data of `calibrate`: bench positions or a raw log's static intervals, and what to say when a
// log has too few of them.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "commands/calibration/calibrate.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/calibration/calibration_stream.hpp"
#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/model_choice.hpp"
#include "numeric/model/registry.hpp"

#include <Eigen/Dense>
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

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
    << d.window << " samples is static when its variance norm stays below " << d.threshold
    << words(" = {threshold-factor} ") << o.threshold_factor << " x the noise floor " << d.still_variance << " ("
    << (d.floor_from_still ? words("the variance of the first {still} ") + shortest(o.still_seconds) + " s"
                           : std::string("the median of the log's quiet windows"))
    << words("), for at least {min-interval} ") << o.min_seconds << " s. ";
  if (d.drifting_runs > 0 && d.intervals.empty()) {
    s << d.drifting_runs << " runs under the threshold turned by more than two degrees (slow motion, not poses): "
      << "the threshold is above the motion"
      << (d.floor_from_still
              ? words("; the {still} period is not still (drop {still}: the floor then comes from the quiet "
                      "windows)")
              : words("; a smaller {threshold-factor} separates the positions"));
  } else if (d.longest_fraction > 0.5) {
    s << "One interval covers " << std::setprecision(2) << 100 * d.longest_fraction
      << " % of the log: the threshold is above the motion"
      << (d.floor_from_still
              ? words("; the {still} period is not still (drop {still}: the floor then comes from the quiet "
                      "windows)")
              : words("; a smaller {threshold-factor} separates the positions"));
  } else if (d.short_runs > 0) {
    s << d.short_runs << words(" still runs were shorter than {min-interval}: a shorter {min-interval} counts them");
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
      throw InputError(o.file, 1, words("a 'position' column makes this bench data, which {rate} does not apply to"));
    return calibration_input(raw_log_from_table(table, o.rate), o);
  }
  for (const auto& row : table.rows)
    for (std::size_t c = 0; c < row.values.size(); ++c)
      if (!std::isfinite(row.values[c]))
        throw InputError(o.file, row.line, "value in column " + table.columns[c] + " is not finite");
  if (!table.has("position") && rows_change_like_a_log(table))
    throw InputError(o.file, 0,
                     "its rows change as a raw log's do (consecutive rows close together, motion between), but it "
                     "has no time column: give the sample rate (rate) or a position column");
  CalibrationInput in;
  in.data = measurements_from_table(table, o.modulus == Modulus::projection);
  return in;
}

}  // namespace

CalibrationInput read_calibration_input(const CalibrateRequest& o) {
  if (o.table) return input_from_table(o, *o.table);
  const bool need_nominal = o.modulus == Modulus::projection;
  const std::string text = read_text_file(o.file);
  if (o.format == LogFormat::text || (o.format == LogFormat::automatic && looks_like_text_log(text)))
    return calibration_input(parse_raw_log(text, o.file, LogFormat::text, o.rate), o);
  TableFormat lenient;  // a raw log's dropouts are counted, not refused
  lenient.nonfinite_allowed = true;
  const CsvTable table = parse_table(text, o.file, lenient);
  if (o.rate > 0 || is_raw_log(table)) {
    if (table.has("position"))
      throw InputError(o.file, 1, words("a 'position' column makes this bench data, which {rate} does not apply to"));
    return calibration_input(raw_log_from_table(table, o.rate), o);
  }
  if (!table.has("position") && time_column(table) < 0 && rows_change_like_a_log(table))
    throw InputError(
        o.file, 0,
        words("its rows change as a raw log's do (consecutive rows close together, motion between), but it "
              "has no time column: give the sample rate with {rate HZ} (or a position column, if it is bench "
              "data with samples of each position in a row)"));
  CalibrationInput in;
  in.data = measurements_from_table(parse_csv(text, o.file), need_nominal);  // strict, as always
  return in;
}

namespace {

// The quietest windows of a log in motion varying more than this many times one sample's white
// noise are slow motion, not still poses (the public logs' still windows: 0.6-1.1 times).
constexpr double kQuietIsMotion = 10;

// The instrument and whether every sample is a position: as given, or as the log shows it (a log
// mostly in motion whose modulus survives the motion is a magnetometer's, turned as magcal, PX4 and
// ArduPilot expect), else from the magnitude where the Earth fixes it.
void decide_instrument(const CalibrateRequest& o, CalibrationInput& in) {
  const LogMotion& m = in.motion;
  const bool tumbling = m.mostly_moving() && m.field_survives();
  if (o.instrument) {
    in.instrument = o.instrument;
    in.instrument_reason = "given";
  } else if (!o.magnitude) {
    in.instrument = Instrument::mag;
    in.instrument_reason = words("a field of unknown strength ({magnitude auto})");
  } else {
    const double magnitude = *o.magnitude;
    for (Instrument i : {Instrument::accel, Instrument::mag})
      if (unit_of_earth_magnitude(i, magnitude)) {
        in.instrument = i;
        in.instrument_reason = std::string(i == Instrument::accel ? "gravity" : "the geomagnetic field") +
                               words("'s strength ({magnitude} ") + magnitude_text(o.magnitude) + ")";
      }
    if (!in.instrument && tumbling) {
      in.instrument = Instrument::mag;
      in.instrument_reason = "the modulus survives the motion of a log turned continuously, as a magnetometer's does";
    }
  }
  // A log taken for a magnetometer's by its magnitude alone whose modulus does not survive the
  // motion is not one (an accelerometer moved with --magnitude auto): only its still poses count.
  if (!o.instrument && in.instrument == Instrument::mag && m.mostly_moving() && !m.field_survives()) {
    in.instrument.reset();
    in.instrument_reason.clear();
    return;
  }
  if (o.instrument == Instrument::mag && m.mostly_moving() && m.ellipsoid && !m.field_survives())
    in.warnings.push_back({o.file, "the modulus changes with the motion: " + motion_text(m) +
                                       "; a magnetometer's field should not (a nearby magnet or current, or an "
                                       "accelerometer's log?): the residual-based standard errors include it"});
  // A magnetometer's log in motion: every sample is a position (magcal's way).
  if (in.instrument && field_survives_motion(*in.instrument) && m.mostly_moving()) {
    if (!m.ellipsoid)
      throw InputError(o.file, 0, "no ellipsoid passes through the log's samples: they are too few or too flat");
    in.every_sample = true;
    in.instrument_reason += "; turned continuously: " + motion_text(m) + ", so every sample is a position";
  }
}

// An accelerometer's log (or one the log cannot show is not) in continuous motion: its samples in
// motion measure acceleration besides gravity, so only still poses count; too few of them is this.
std::string moving_log_message(const LogMotion& m, const IntervalDetection& d, const std::string& need) {
  return "the log never stands still long enough: " + motion_text(m) + ", and " + std::to_string(d.intervals.size()) +
         " still intervals were found (" + need +
         words(
             "). An accelerometer measures gravity only at rest: record still poses of a second or more; a "
             "magnetometer's log is calibrated sample by sample ({instrument mag})");
}

// det(covariance)^(1/P) of the noise-based errors of the calibration a detection's positions give
// under `model`, or none.
std::optional<double> detection_score(const RawLog& log, const IntervalDetection& d, const CalibrateRequest& o,
                                      ModelKind model) {
  if (static_cast<int>(d.intervals.size()) < model_parameters(model) + 1) return std::nullopt;
  AnyUnitsOptions ao;
  ao.modulus = o.modulus;
  ao.magnitude_auto = !o.magnitude;
  ao.magnitude = o.magnitude.value_or(1.0);
  ao.weight_by_samples = o.weights == PositionWeights::samples;
  ao.model = model;
  try {
    const AnyUnitsCalibration fit = calibrate_any_units(o.file, interval_positions(log, d), ao);
    if (!fit.estimate.summary.converged() || fit.noise_covariance.size() == 0) return std::nullopt;
    // Under --model auto a candidate scores under the model auto would take for it.
    if (!o.model && !judge_layout(model, Program{fit.directions}, ao.magnitude_auto || fit.started).carried)
      return std::nullopt;
    const Eigen::LDLT<Eigen::MatrixXd> c(fit.noise_covariance);
    if (c.info() != Eigen::Success || !(c.vectorD().minCoeff() > 0)) return std::nullopt;
    return std::exp(c.vectorD().array().log().sum() / static_cast<double>(fit.noise_covariance.rows()));
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The detection of a raw log's still poses, chosen among the candidates by the predicted errors of
// the calibration each gives: under the requested model, else the richest linear model under which
// some candidate calibrates.
void choose_for_log(const CalibrateRequest& o, const CalibrationStream& stream, CalibrationInput& in) {
  std::vector<ModelKind> models;
  if (o.model)
    models.push_back(*o.model);
  else
    models = auto_choice_models();  // richest first
  for (const ModelKind model : models) {
    const auto chosen =
        stream.choose([&](const IntervalDetection& d) { return detection_score(stream.log(), d, o, model); });
    if (!chosen) continue;
    in.chosen = chosen;
    in.detection = chosen->detection;
    return;
  }
}

// The log through the stream's detection: as one last chunk (the batch: the log itself, not a copy),
// or in chunks of --chunk rows as a logger delivers them; with the adaptive choice's candidates
// unless the detection's options were given.
CalibrationStream stream_of(RawLog&& log, const CalibrateRequest& o) {
  CalibrationStream stream(log.file, o.intervals, !o.intervals_given);
  if (log.size() == 0) return stream;  // no chunk at all, as a logger that never sent one
  if (o.chunk_rows <= 0 || o.chunk_rows >= log.size()) {
    stream.add(std::move(log), true);
    return stream;
  }
  for (int begin = 0; begin < log.size(); begin += o.chunk_rows) {
    const int end = std::min(log.size(), begin + o.chunk_rows);
    RawLog chunk;
    chunk.file = log.file;
    chunk.t.assign(log.t.begin() + begin, log.t.begin() + end);
    chunk.samples.assign(log.samples.begin() + begin, log.samples.begin() + end);
    chunk.lines.assign(log.lines.begin() + begin, log.lines.begin() + end);
    stream.add(std::move(chunk), end == log.size());
  }
  return stream;
}

// What the stream's log gives calibrate, all but the log itself (the caller copies or takes it).
CalibrationInput input_of(const CalibrationStream& stream, const CalibrateRequest& o);

// A raw log's positions are found, not given, so no nominal direction comes with them: said before the log is
// streamed, by both entries.
void refuse_projection(const CalibrateRequest& o) {
  if (o.modulus == Modulus::projection)
    throw InputError(o.file, 0, "a raw log has no nominal directions: the projection modulus needs them");
}

}  // namespace

CalibrationInput calibration_input(RawLog log, const CalibrateRequest& o) {
  refuse_projection(o);
  CalibrationStream stream = stream_of(std::move(log), o);
  CalibrationInput in = input_of(stream, o);
  in.log = std::move(stream).release_log();
  return in;
}

CalibrationInput calibration_input(const CalibrationStream& stream, const CalibrateRequest& o) {
  refuse_projection(o);
  CalibrationInput in = input_of(stream, o);
  in.log = stream.log();
  return in;
}

namespace {

CalibrationInput input_of(const CalibrationStream& stream, const CalibrateRequest& o) {
  // --model auto takes the richest model the positions carry, down to offsets only.
  const std::vector<ModelKind> automatic = auto_choice_models();  // richest first
  const int needed = model_parameters(o.model ? *o.model : automatic.back());
  std::string need;
  if (o.model) {
    need = words("{model} ") + std::string(model_name(*o.model)) + " needs at least " + std::to_string(needed) +
           " positions";
  } else {  // "paper9 needs at least 9 positions (axis6 6, bias3 3)"
    need = std::string(model_name(automatic[0])) + " needs at least " + std::to_string(model_parameters(automatic[0])) +
           " positions";
    std::string others;
    for (std::size_t k = 1; k < automatic.size(); ++k)
      others += (others.empty() ? "" : ", ") + std::string(model_name(automatic[k])) + " " +
                std::to_string(model_parameters(automatic[k]));
    if (!others.empty()) need += " (" + others + ")";
  }
  const RawLog& log = stream.log();
  CalibrationInput in;
  in.chunks = stream.chunks();
  in.detection = stream.detection();
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
  in.motion = judge_motion(log, d);
  decide_instrument(o, in);
  if (in.every_sample) {
    in.data = sample_positions(log, d.usable, in.sample_index);
    if (in.data.size() < static_cast<std::size_t>(needed))
      throw InputError(o.file, 0, std::to_string(in.data.size()) + " usable samples; " + need);
    return in;
  }
  choose_for_log(o, stream, in);  // a stream of given options has no candidates
  if (d.intervals.size() < static_cast<std::size_t>(needed))
    throw InputError(o.file, 0,
                     in.motion.mostly_moving() && !d.floor_from_still ? moving_log_message(in.motion, d, need)
                                                                      : too_few_message(d, o.intervals, need));
  // A log in motion whose quietest windows still move far more than one sample's noise has no
  // still poses at all, only slow phases of its motion: an accelerometer there measures more than
  // gravity. (A sensor whose noise is not white can show a floor a few times its second-difference
  // noise: the factor leaves room for that; --still sets the floor from a known still start.)
  const double white = in.motion.noise.cwiseProduct(in.motion.noise).norm();
  if (in.motion.mostly_moving() && !d.floor_from_still && d.still_variance > kQuietIsMotion * white)
    throw InputError(o.file, 0,
                     moving_log_message(in.motion, d, need) + "; its quietest windows vary " +
                         shortest(d.still_variance / white) + " times as much as one sample's noise");
  in.data = interval_positions(log, in.detection);
  return in;
}

}  // namespace

namespace {

std::string not_a_magnitude(const std::string& text) { return "must be a positive number or auto, got '" + text + "'"; }

}  // namespace

std::optional<double> magnitude_value(const std::string& s) {
  if (s == "auto") return std::nullopt;
  return std::stod(s);
}

std::string magnitude_text(const std::optional<double>& magnitude) {
  return magnitude ? shortest_text(*magnitude) : "auto";
}

std::string magnitude_problem(const std::string& s) {
  if (s == "auto") return "";
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size()) return magnitude_problem(std::optional<double>(v)).empty() ? "" : not_a_magnitude(s);
  } catch (...) {
  }
  return not_a_magnitude(s);
}

std::string magnitude_problem(const std::optional<double>& magnitude) {
  return !magnitude || (std::isfinite(*magnitude) && *magnitude > 0) ? "" : not_a_magnitude(magnitude_text(magnitude));
}

void check_calibrate_request(const CalibrateRequest& o) {
  if (const std::string problem = magnitude_problem(o.magnitude); !problem.empty())
    throw UsageError(words("calibrate: {magnitude} ") + problem);
  // A model whose correction is not linear has a cubic term relative to |I| (cubic12).
  if (o.model && !corrects_linearly(meter_slots(*o.model)) && !o.magnitude)
    throw UsageError(
        words("calibrate: {magnitude auto} does not work with {model cubic12}: its cubic term is relative to "
              "|I|, which would be one more unknown; give |I|"));
  if (o.model && !model_supports(*o.model, ModelCapability::region_limits) && !o.regions.empty())
    throw UsageError(words("calibrate: {region} (the advice on what to add) works with the ") +
                     models_supporting(ModelCapability::region_limits) + " model only");
  if (!(o.rate >= 0) || !std::isfinite(o.rate)) throw UsageError(words("calibrate: {rate} must be a positive number"));
}

}  // namespace scalcal::commands
