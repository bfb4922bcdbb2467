// A gyro's calibration by rate table, known turns or hand rotations (calibrate_gyro.hpp).
#include "commands/calibration/calibrate_gyro.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <Eigen/SVD>

#include "commands/core/usage_error.hpp"
#include "numeric/calibration/units.hpp"
#include "numeric/gyro/gravity_poses.hpp"
#include "numeric/gyro/gyro_simulation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/augment.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::commands {

const char* gyro_method_name(GyroMethod m) {
  return m == GyroMethod::rate_table ? "rate_table" : m == GyroMethod::known_turns ? "known_turns" : "hand_rotations";
}

GyroMethod gyro_method(const GyroCalibrateRequest& r) {
  if (!r.accelerometer.empty()) {
    if (!r.accelerometer_magnitude)
      throw UsageError(words(
          "calibrate: {accelerometer} needs {accelerometer-magnitude} (|g| in the accelerometer's units, or auto)"));
    if (r.magnitude || r.turn_angle_deg)
      throw UsageError(
          words("calibrate: hand rotations ({accelerometer}) take no {magnitude} or {turn-angle}: the gyro's "
                "rates come from the accelerometer's poses"));
    if (r.latitude_deg)
      throw UsageError(words("calibrate: {latitude} is for a rate table ({magnitude}), not hand rotations"));
    return GyroMethod::hand_rotations;
  }
  if (r.accelerometer_magnitude)
    throw UsageError(words("calibrate: {accelerometer-magnitude} needs {accelerometer ACC_LOG}"));
  if (r.turn_angle_deg) {
    if (r.magnitude)
      throw UsageError(
          words("calibrate: {turn-angle} (known turns) and {magnitude} (a rate table) exclude each other"));
    if (!(*r.turn_angle_deg > 0) || !std::isfinite(*r.turn_angle_deg))
      throw UsageError(words("calibrate: {turn-angle} must be a positive number of degrees"));
    if (r.latitude_deg)
      throw UsageError(words("calibrate: {latitude} is for a rate table ({magnitude}), not known turns"));
    return GyroMethod::known_turns;
  }
  if (!r.magnitude)
    throw UsageError(
        words("calibrate {instrument gyro}: say how the gyro was turned: {magnitude RATE|auto|column:NAME} (a rate "
              "table), {turn-angle DEG} (known turns) or {accelerometer ACC_LOG} {accelerometer-magnitude G} (hand "
              "rotations)"));
  if (const std::string problem = magnitude_problem(r.magnitude->rate); !problem.empty())
    throw UsageError(words("calibrate: {magnitude} ") + problem + " (or column:NAME)");
  if (r.latitude_deg && !(std::abs(*r.latitude_deg) <= 90))
    throw UsageError(words("calibrate: {latitude} must be in [-90, 90] degrees"));
  return GyroMethod::rate_table;
}

namespace {

// Physical units per rad/s: the Earth's rate, a turn's angle and a hand rotation's matrix are made
// in rad/s and turned into the calibration's physical unit.
double per_rad_per_s(const std::string& unit) {
  if (unit.empty()) return 1;
  const auto u = parse_unit(unit);
  if (!u || u->quantity != Quantity::angular_rate)
    throw UsageError(
        words("calibrate {instrument gyro}: {units PHYSICAL} must be a unit of angular rate (rad/s, deg/s), got '") +
        unit + "'");
  return 1 / u->base;
}

Vec3 rotation_vector(const Mat3& M) {
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Mat3 Q = svd.matrixU() * svd.matrixV().transpose();
  const double c = std::clamp((Q.trace() - 1) / 2, -1.0, 1.0), angle = std::acos(c);
  const Vec3 s(Q(2, 1) - Q(1, 2), Q(0, 2) - Q(2, 0), Q(1, 0) - Q(0, 1));
  return s.norm() < 1e-300 ? Vec3::Zero() : Vec3(angle * s.normalized());
}

// A signed per-row column (the table's commanded rate), by the log's line numbers.
std::map<int, double> column_by_line(const std::string& file, const std::string& name) {
  TableFormat lenient;
  lenient.nonfinite_allowed = true;
  const CsvTable table = parse_table(read_text_file(file), file, lenient);
  if (!table.has(name)) throw InputError(file, 1, "no column '" + name + words("' ({magnitude column:}") + name + ")");
  const std::size_t c =
      static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin());
  std::map<int, double> out;
  for (const auto& row : table.rows) out[row.line] = row.values[c];
  return out;
}

// The items (segments or turns) and rests: the model asked for, or the richest they carry.
void fit_items(const GyroCalibrateRequest& q, GyroCalibrateResult& r) {
  if (q.model) {
    gyro::KnownModulusOptions o;
    o.model = *q.model;
    r.scalar = gyro::calibrate_known_moduli(q.file, r.items, r.rests, o);
    r.model_reason = "requested";
  } else {
    r.scalar = gyro::calibrate_known_moduli_auto(q.file, r.items, r.rests, r.model_reason);
  }
}

// Rests are the largest group of two or more equal outputs (gyro::segment_rate_log): a lone rest is left
// among the segments, where it reads as a turn at the table's rate and pulls every parameter (a
// rehearsal with one rest: offsets of 0.21 rad/s against a true 0.005, exit 0). A segment whose output
// per unit of its rate is under half the segments' median is such a rest, and the log is refused.
void refuse_lone_rests(const GyroCalibrateRequest& q, const gyro::RateLogSegments& s,
                       const std::vector<double>& rates) {
  std::vector<double> ratio;
  for (std::size_t i = 0; i < s.segments.size(); ++i) ratio.push_back(s.segments[i].mean.norm() / rates[i]);
  if (ratio.size() < 3) return;
  std::vector<double> sorted = ratio;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    if (ratio[i] >= 0.5 * median) continue;
    char what[160];
    std::snprintf(what, sizeof what,
                  "the output from %.4g to %.4g s is %.3g %% of the other segments' per unit of rate",
                  s.segments[i].span.start, s.segments[i].span.stop, 100 * ratio[i] / median);
    throw InputError(q.file, s.segments[i].line,
                     std::string(what) +
                         ": the table at rest, not turning. Rests are found as two or more equal outputs and this log "
                         "has " +
                         std::to_string(s.rests.size()) +
                         ": record a rest between segments (at least two in all), or cut this one out");
  }
}

void rate_table(const GyroCalibrateRequest& q, const RawLog& log, GyroCalibrateResult& r) {
  const gyro::RateLogSegments s = gyro::segment_rate_log(log, q.intervals);
  r.detection = s.detection;
  r.rests = s.rests;
  std::vector<double> rates, senses;
  if (!q.magnitude->column.empty()) {
    const auto column = column_by_line(q.file, q.magnitude->column);
    for (const auto& seg : s.segments) {
      std::vector<double> v;
      for (int i = seg.span.begin; i <= seg.span.end; ++i) {
        const auto it = column.find(log.lines[static_cast<std::size_t>(i)]);
        if (it != column.end() && std::isfinite(it->second)) v.push_back(it->second);
      }
      if (v.empty()) throw InputError(q.file, seg.line, "the rate column has no value in this segment");
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
      const double m = v[v.size() / 2];
      if (m == 0) throw InputError(q.file, seg.line, "the rate column is 0 in a segment where the gyro turns");
      rates.push_back(std::abs(m));
      senses.push_back(m > 0 ? 1 : -1);
    }
  } else {
    rates.assign(s.segments.size(), q.magnitude->rate.value_or(1.0));
  }
  if (q.latitude_deg) {
    if (senses.empty())
      throw UsageError(
          words("calibrate: {latitude} needs each segment's sense: give the table's signed rate as a column "
                "({magnitude column:NAME}, positive counterclockwise seen from above)"));
    // The Earth's rate in east, north, up is Omega (0, cos phi, sin phi); along the table's axis it adds to
    // every turn's rate, across it it turns with the table and averages out over a segment's whole turns.
    const double phi = *q.latitude_deg * M_PI / 180;
    const double axial =
        gyro::kEarthRate * q.table_axis.dot(Vec3(0, std::cos(phi), std::sin(phi))) * per_rad_per_s(q.physical_units);
    for (std::size_t i = 0; i < rates.size(); ++i) rates[i] = std::abs(rates[i] + senses[i] * axial);
  }
  refuse_lone_rests(q, s, rates);
  r.items = gyro::segment_items(s.segments, rates);
  fit_items(q, r);
}

void known_turns(const GyroCalibrateRequest& q, const RawLog& log, GyroCalibrateResult& r) {
  const gyro::RateLogSegments s = gyro::segment_rate_log(log, q.intervals);
  r.detection = s.detection;
  r.rests = s.rests;
  if (s.rests.size() < 2)
    throw InputError(
        q.file, 0,
        "found " + std::to_string(s.rests.size()) + " rests; known turns need a rest before and after each turn");
  Vec3 rest = Vec3::Zero();
  std::vector<double> sd;
  for (const auto& x : s.rests) rest += x.mean, sd.push_back(x.sd.mean());
  rest /= static_cast<double>(s.rests.size());
  std::nth_element(sd.begin(), sd.begin() + static_cast<std::ptrdiff_t>(sd.size() / 2), sd.end());
  const auto motions = gyro::turns_between_rests(log, s);
  const auto turns = gyro::largest_turns(motions, rest);
  r.motions_skipped = static_cast<int>(motions.size() - turns.size());
  const double angle = *q.turn_angle_deg * M_PI / 180 * per_rad_per_s(q.physical_units);
  r.items = gyro::turn_items(turns, {angle}, sd[sd.size() / 2], s.detection.sample_period);
  for (std::size_t i = 0; i < turns.size(); ++i) {
    r.items[i].start = log.t[static_cast<std::size_t>(turns[i].begin)];
    r.items[i].stop = log.t[static_cast<std::size_t>(turns[i].end)];
  }
  fit_items(q, r);
}

void hand_rotations(const GyroCalibrateRequest& q, const RawLog& log, GyroCalibrateResult& r) {
  CalibrateRequest a;
  a.file = q.accelerometer;
  a.magnitude = *q.accelerometer_magnitude;
  a.format = q.format;
  a.rate = q.rate;
  a.intervals = q.intervals;
  a.suggest = 0;
  CalibrationInput in = read_calibration_input(a);
  if (!in.log)
    throw InputError(q.accelerometer, 0,
                     "is bench data (a position column); hand rotations need the accelerometer's raw log");
  const RawLog acc = *in.log;
  r.accelerometer = calibrate(a, std::move(in));
  r.detection = *r.accelerometer->detection;
  for (const auto& w : r.accelerometer->warnings) r.warnings.push_back(w);
  r.poses = gyro::gravity_poses(acc, log, r.detection.intervals, r.accelerometer->fit.correction);
  r.hand = gyro::calibrate_hand_rotations(log, r.poses);
  const double k = per_rad_per_s(q.physical_units);
  r.matrix = k * r.hand->matrix;
  r.offset = r.hand->offset;
}

// The measured program's criteria, efficiency and the positions to add (paper9's advice as
// calibrate gives it, on the sphere: the table's axis may point anywhere in the meter's frame).
void judge_program(GyroCalibrateResult& r) {
  const Program measured{r.scalar->directions};
  const ModelKind model = r.scalar->model;
  r.program = evaluate(model, measured);
  const int P = model_parameters(model);
  for (CriterionKind c : kCriteria) {
    const double v = r.program->value(c);
    double limit = NAN;
    if (model_supports(model, ModelCapability::criteria_native) && has_limit(c))
      limit = limit_value(c, sphere_region());
    else if (const auto stated = stated_limit(model, criterion_name(c)))
      limit = stated->value;
    r.efficiency.push_back(std::isfinite(limit) && std::isfinite(v) ? efficiency(c, limit, v, P) : NAN);
  }
  if (r.program->full_rank() && measured.size() <= 60)
    r.suggested = augment_program(measured, 3, CriterionKind::D, sphere_region(), model).added;
}

}  // namespace

bool GyroCalibrateResult::converged() const {
  if (scalar) return scalar->summary.converged();
  return hand && hand->summary.converged() && (!accelerometer || accelerometer->converged());
}

GyroCalibrateResult calibrate_gyro(const GyroCalibrateRequest& q) {
  GyroCalibrateResult r;
  r.request = q;
  r.method = gyro_method(q);
  if (r.request.physical_units.empty() && r.method != GyroMethod::rate_table) r.request.physical_units = "rad/s";
  r.warnings = q.warnings;
  const RawLog log = read_raw_log(q.file, q.format, q.rate);
  r.rows = log.size();
  if (r.method == GyroMethod::rate_table) rate_table(q, log, r);
  if (r.method == GyroMethod::known_turns) known_turns(q, log, r);
  if (r.method == GyroMethod::hand_rotations) hand_rotations(q, log, r);
  if (r.scalar) {
    judge_program(r);
    r.matrix = r.scalar->correction.matrix;
    r.offset = r.scalar->correction.offset;
    r.paper_form = r.scalar->correction;
  } else {
    r.paper_form = canonical_correction(r.matrix, r.offset);
    if (r.paper_form) r.rotation = rotation_vector(r.matrix * r.paper_form->matrix.inverse());
  }
  if (!r.matrix.allFinite() || !r.offset.allFinite()) throw InputError(q.file, 0, "the fit is not finite");
  // The white noise of one sample: the rests' median scatter per axis (raw units) through the matrix.
  std::vector<double> sd;
  if (r.hand) {
    for (const auto& p : r.poses) {
      Vec3 s = Vec3::Zero(), s2 = Vec3::Zero();
      int n = 0;
      for (int i = p.begin; i <= p.end; ++i)
        if (log.finite(i))
          s += log.samples[static_cast<std::size_t>(i)], s2 += log.samples[static_cast<std::size_t>(i)].cwiseAbs2(),
              ++n;
      if (n > 1) sd.push_back(std::sqrt(std::max(0.0, ((s2 - s.cwiseAbs2() / n) / (n - 1)).mean())));
    }
  } else {
    for (const auto& x : r.rests) sd.push_back(x.sd.norm() / std::sqrt(3.0));
  }
  if (!sd.empty()) {
    std::nth_element(sd.begin(), sd.begin() + static_cast<std::ptrdiff_t>(sd.size() / 2), sd.end());
    r.noise = sd[sd.size() / 2] * r.matrix.norm() / std::sqrt(3.0);
  }
  return r;
}

}  // namespace scalcal::commands
