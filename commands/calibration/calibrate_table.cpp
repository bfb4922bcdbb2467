// The options of `scalcal calibrate` (calibrate.hpp) and the request they make.
#include "commands/calibration/calibrate.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

std::vector<std::string> model_choices() {
  std::vector<std::string> c = {"auto"};
  for (const auto& m : model_names()) c.push_back(m);
  return c;
}

Option instrument_option() {
  Option o = choice_option("--instrument", {"accel", "mag", "gyro"},
                           "the meter: accel (still poses only: motion adds acceleration), mag (every sample, turned "
                           "continuously or held still), gyro",
                           "");
  o.fallback_text =
      words("from the log (a tumbling log whose modulus survives the motion is a magnetometer's) and {magnitude}");
  return o;
}

// --units RAW,PHYSICAL: RAW counts or a unit, PHYSICAL a unit, both of the instrument's quantity.
void read_units(const Values& v, CalibrateRequest& q) {
  const std::string units = v.text("--units");
  if (units.empty()) return;
  const auto comma = units.find(',');
  if (comma == std::string::npos || comma == 0 || comma + 1 == units.size() ||
      units.find(',', comma + 1) != std::string::npos)
    throw UsageError(words("{units}: expected RAW,PHYSICAL (for example counts,m/s^2), got '") + units + "'");
  q.raw_units = units.substr(0, comma);
  q.physical_units = units.substr(comma + 1);
  const auto raw = parse_unit(q.raw_units), physical = parse_unit(q.physical_units);
  if (!raw && !is_count_unit(q.raw_units))
    throw UsageError(words("{units}: RAW '") + q.raw_units + "' is not counts nor a unit scalcal knows (" +
                     unit_names() + ")");
  if (!physical)
    throw UsageError(words("{units}: PHYSICAL '") + q.physical_units + "' is not a unit scalcal knows (" +
                     unit_names() + ")");
  if (raw && raw->quantity != physical->quantity)
    throw UsageError(words("{units}: ") + q.raw_units + " and " + q.physical_units + " are not units of one quantity");
  if (q.instrument && physical->quantity != quantity_of(*q.instrument))
    throw UsageError(words("{units}: ") + q.physical_units + " is not a unit of " +
                     std::string(quantity_name(quantity_of(*q.instrument))) + ", which a " +
                     std::string(instrument_noun(*q.instrument)) + " measures");
  if (!q.magnitude)
    throw UsageError(words("{units}: with {magnitude auto} the correction maps the field to modulus 1, not to ") +
                     q.physical_units + words("; give the field's strength as {magnitude} to calibrate in ") +
                     q.physical_units + words(" (the raw units alone: {units} ") + q.raw_units + "," +
                     q.physical_units + " needs a magnitude)");
}

}  // namespace

namespace {

// --model: auto, a registered model, or a thermal model BASE+Tk (numeric/thermal/thermal_model.hpp).
Option calibrate_model_option() {
  Option model =
      choice_option("--model", model_choices(),
                    "the calibration model: auto (the richest of paper9, axis6, bias3 that the positions "
                    "identify), or one of the registered models, or a thermal model BASE+Tk / BASE+bias:Tk over "
                    "a base with the thermal capability (paper9+T2, bias3+T3; a log with a temperature "
                    "column: temp, temperature or t_c)",
                    "auto");
  model.value_name = "auto|NAME";
  model.kind = OptionKind::text;
  model.why_bad = [choices = model.choices](const std::string& text) -> std::string {
    for (const auto& c : choices)
      if (text == c) return "";
    try {
      if (parse_thermal_model(text)) return "";
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "must be auto, one of the registered models or BASE+Tk (got '" + text + "')";
  };
  model.choices.clear();
  return model;
}

// --chunk: a raw log as a stream (numeric/calibration/calibration_stream.hpp).
Option chunk_option() {
  return integer_option("--chunk", 1, 1000000000,
                        "take a raw log in chunks of this many rows, as a logger delivers them: each sample is judged "
                        "still or moving once, from the rows up to half a window after it, never again",
                        "rows", "", "the whole log at once");
}

Option magnitude_option() {
  Option o = text_option("--magnitude", "M|auto",
                         words("modulus |I| of the measured vector, or auto for a field of unknown strength; for a "
                               "gyro ({instrument gyro}) the rate table's rate, auto, or column:NAME (the log's signed "
                               "rate per row)"),
                         "physical units", "");
  o.fallback_text = words("required, unless {instrument gyro} with {turn-angle} or {accelerometer}");
  o.why_bad = [](const std::string& m) { return m.rfind("column:", 0) == 0 ? "" : magnitude_problem(m); };
  return o;
}

// --accelerometer-magnitude: refused as --magnitude is, by the option table (in every front end's words).
Option accelerometer_magnitude_option() {
  Option o =
      text_option("--accelerometer-magnitude", "G|auto",
                  words("hand rotations ({instrument gyro}): the accelerometer's |g|"), "the accelerometer's units");
  o.why_bad = [](const std::string& g) { return magnitude_problem(g); };
  return o;
}

}  // namespace

const CommandTable& calibrate_table() {
  Option measurements = text_option(
      "--measurements", "FILE",
      "bench data: CSV with ix,iy,iz [,position] [,x,y,z], or a raw log: CSV with a time column (t, t_s, time, "
      "time_s or timestamp) and ix,iy,iz, or text t ix iy iz",
      "file path", kRequired);
  measurements.takes_columns = true;
  const Option model = calibrate_model_option();
  Option still = positive_option("--still",
                                 "take the noise floor from the log's initial still period of this length (default: "
                                 "from the log's quietest windows, no still start needed)",
                                 "seconds", "");
  still.fallback_text = "from the log's quietest windows";
  Option rate = positive_option("--rate",
                                "the sample rate of a raw log without a time column (or whose time column is the "
                                "sample index): row k is at k / HZ seconds; makes a CSV with ix,iy,iz a raw log",
                                "Hz", "");
  rate.value_name = "HZ";
  rate.fallback_text = "the log's time column";
  const StaticIntervalOptions d;
  static const CommandTable table{
      "calibrate",
      "scalar calibration (eqs. 3-6) in any units, from grouped samples or a raw log, with the model the positions "
      "identify: bias, scale factors, non-orthogonality with honest standard errors, the full correction, each "
      "position's residual, the program's quality and what to add",
      20,
      {measurements,
       magnitude_option(),
       model,
       temperature_option(),
       choice_option("--modulus", {"norm", "projection"},
                     "the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)", "norm"),
       choice_option("--format", {"auto", "csv", "text"},
                     "the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz, no "
                     "header)",
                     "auto"),
       rate,
       still,
       positive_option("--window", "the moving variance's window in a raw log", "seconds",
                       shortest_text(d.window_seconds)),
       positive_option("--threshold-factor",
                       "static where the window's variance norm stays below this times the noise floor", "none",
                       shortest_text(d.threshold_factor)),
       positive_option("--min-interval", "the shortest static interval that counts as a position", "seconds",
                       shortest_text(d.min_seconds)),
       chunk_option(),
       choice_option("--weights", {"auto", "samples", "positions"},
                     "each position's weight: its number of samples, or 1; auto: positions for a raw log, samples "
                     "otherwise",
                     "auto"),
       flag_option("--keep-outliers",
                   "keep samples more than 10 robust scales from their position's median (excluded by default)"),
       named(integer_option("--suggest", 0, kMaxSuggestions, "how many positions to suggest adding (never one twice)",
                            "positions", "3"),
             "K"),
       criterion_option(),
       region_option(),
       text_option("--program", "FILE",
                   "the program the data measured (a program or plan file): its '# region:' line judges the efficiency "
                   "and the suggestions (without it, the measurements file's own region line does)",
                   "file path"),
       tolerance_option(),
       text_option("--sensor", "LABEL", words("a label of the meter for the calibration file ({out})")),
       text_option(
           "--units", "RAW,PHYSICAL",
           words("the units of the raw data (counts, or a unit) and of the corrected vectors (a unit), for the "
                 "calibration file and the exports (default: from {magnitude} where the Earth fixes them: 9.81 is "
                 "m/s^2, 1 is g, 50 is uT)")),
       instrument_option(),
       number_option(
           "--turn-angle", 0, 36000,
           words("known turns ({instrument gyro}): each turn's angle (the largest motions between rests are the "
                 "turns)"),
           "degrees", ""),
       text_option(
           "--accelerometer", "ACC_LOG",
           words("hand rotations ({instrument gyro}): the log of an accelerometer moved with the gyro (the same "
                 "rows); it is calibrated first and the gyro's matrix maps into its corrected frame"),
           "file path"),
       accelerometer_magnitude_option(),
       number_option(
           "--latitude", -90, 90,
           words("a rate table ({instrument gyro}): add the Earth's rate to each segment's (its part along the "
                 "table's axis, {table-axis}; needs {magnitude column:NAME} for each turn's sense)"),
           "degrees", ""),
       text_option("--table-axis", "E,N,U",
                   words("a rate table with {latitude}: the table's axis in east, north, up, positive turns "
                         "counterclockwise seen from its tip (normalised; default 0,0,1: vertical)")),
       out_option("also write the calibration (the JSON object, with \"converged\") to FILE, for `scalcal correct`",
                  "CAL.json"),
       json_option("print one JSON object")}};
  return table;
}

void read_log_options(const Values& v, LogFormat& format, double& rate, StaticIntervalOptions& intervals) {
  format = log_format_named(v.text("--format"));
  if (v.given("--rate")) rate = v.number("--rate");
  if (v.given("--still")) intervals.still_seconds = v.number("--still");
  intervals.window_seconds = v.number("--window");
  intervals.threshold_factor = v.number("--threshold-factor");
  intervals.min_seconds = v.number("--min-interval");
}

CalibrateRequest calibrate_request(const Values& v) {
  CalibrateRequest q;
  q.file = v.text("--measurements");
  if (const auto it = v.tables.find("--measurements"); it != v.tables.end()) q.table = it->second;
  if (!v.given("--magnitude"))
    throw UsageError(
        words("{magnitude M|auto} is required (a gyro's {instrument gyro} takes {turn-angle} or "
              "{accelerometer} instead)"));
  for (const char* o : {"--turn-angle", "--accelerometer", "--accelerometer-magnitude", "--latitude", "--table-axis"})
    if (v.given(o)) throw UsageError(option_word(o) + words(" belongs to {instrument gyro}"));
  const std::string magnitude = v.text("--magnitude");
  if (magnitude.rfind("column:", 0) == 0)
    throw UsageError(words("{magnitude column:NAME} is a rate table's ({instrument gyro})"));
  q.magnitude = magnitude_value(magnitude);  // a positive number or auto: the option's why_bad saw to it
  q.modulus = v.text("--modulus") == "projection" ? Modulus::projection : Modulus::norm;
  read_log_options(v, q.format, q.rate, q.intervals);
  if (v.given("--chunk")) q.chunk_rows = static_cast<int>(v.integer("--chunk"));
  q.intervals_given =
      v.given("--window") || v.given("--threshold-factor") || v.given("--min-interval") || v.given("--still");
  if (v.text("--weights") != "auto")
    q.weights = v.text("--weights") == "samples" ? PositionWeights::samples : PositionWeights::positions;
  q.keep_outliers = v.flag("--keep-outliers");
  q.suggest = static_cast<int>(v.integer("--suggest"));
  q.criterion = criterion_of(v);
  q.program = v.text("--program");
  if (!v.given("--region") && !v.given("--program") && !q.table)
    q.regions = regions_for({}, q.file, q.warnings);
  else
    q.regions = regions_for(v.list("--region"), q.program, q.warnings);
  q.tolerance_deg = v.number("--tolerance");
  q.sensor = v.text("--sensor");
  if (v.given("--instrument")) q.instrument = parse_instrument(v.text("--instrument"));
  if (q.instrument == Instrument::gyro)
    throw UsageError(words(
        "{instrument gyro}: a gyroscope's calibration is calibrate_gyro's (commands/calibration/calibrate_gyro.hpp), "
        "not this "
        "request's"));
  read_units(v, q);
  q.thermal = parse_thermal_model(v.text("--model"));
  if (v.given("--temperature")) {
    if (!q.thermal) throw UsageError(words("{temperature} needs a thermal model, {model BASE+Tk} (e.g. paper9+T2)"));
    q.temperature = parse_temperature_range(v.text("--temperature"));
  }
  if (q.thermal) {
    if (!model_supports(q.thermal->base, ModelCapability::thermal_base))
      throw UsageError(words("{model} ") + q.thermal->name() + ": a thermal log is fitted under " +
                       calibrated_thermal_models());
    return q;
  }
  if (v.text("--model") != "auto") q.model = *parse_model(v.text("--model"));
  check_calibrate_request(q);
  return q;
}

}  // namespace scalcal::commands
