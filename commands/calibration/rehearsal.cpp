// Rehearsal logs (rehearsal.hpp).
#include "commands/calibration/rehearsal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "commands/calibration/tumbling_rehearsal.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

constexpr double kSpeedDegPerS = 45, kMinMoveS = 1, kNearDeg = 5, kSwingDeg = 20;

double angle_deg(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI; }

// A unit vector perpendicular to a.
Vec3 perpendicular(const Vec3& a) {
  const Vec3 ref = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (ref - ref.dot(a) * a).normalized();
}

// The point a fraction s of the way from a to b along their great circle.
Vec3 along(const Vec3& a, const Vec3& b, double s) {
  Vec3 axis = a.cross(b);
  if (axis.norm() < 1e-12) axis = a.cross(perpendicular(a));  // antipodal (or equal): any great circle
  const double total = std::atan2(a.cross(b).norm(), a.dot(b));
  return Eigen::AngleAxisd(s * total, axis.normalized()) * a;
}

Vec3 read_triple(const Json& j, const std::string& key, const std::string& file) {
  if (!j.contains(key) || !j[key].is_array() || j[key].size() != 3)
    throw InputError(file, 0, "the meter needs '" + key + "': three numbers");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    if (!j[key][static_cast<std::size_t>(k)].is_number()) throw InputError(file, 0, "'" + key + "' must hold numbers");
    v(k) = j[key][static_cast<std::size_t>(k)].get<double>();
  }
  return v;
}

// bias (file units), scale_deviation, nonorthogonality (rad), as calibrate --json writes them.
Meter meter_from_file(const RehearsalRequest& q) {
  const Json j = parse_json_file_text(read_text_file(q.meter_file), q.meter_file);
  if (!j.is_object())
    throw InputError(q.meter_file, 0, "expected a JSON object with bias, scale_deviation, nonorthogonality");
  Vec9 X;
  X << read_triple(j, "bias", q.meter_file) / q.magnitude, read_triple(j, "scale_deviation", q.meter_file),
      read_triple(j, "nonorthogonality", q.meter_file);
  return Meter::from_parameters(X, q.magnitude);
}

class LogWriter {
 public:
  LogWriter(RehearsalResult& r, const Meter& meter, GaussianSource& noise)
      : r_(r), meter_(meter), noise_(noise), dt_(1 / r.request.rate_hz) {}

  void sample(const Vec3& eta, int position) {
    const RehearsalRequest& q = r_.request;
    const Vec3 e(noise_(), noise_(), noise_());
    r_.t.push_back(static_cast<double>(r_.t.size()) * dt_);
    r_.samples.push_back(meter_.measure(q.magnitude * eta) + q.noise * q.magnitude * e);
    r_.position.push_back(position);
  }
  void rest(const Vec3& eta, double seconds, int position) {
    const double start = static_cast<double>(r_.t.size()) * dt_;
    const long n = std::max(1L, std::lround(seconds / dt_));
    for (long k = 0; k < n; ++k) sample(eta, position);
    r_.rests.emplace_back(start, r_.t.back());
  }
  void move(const Vec3& a, const Vec3& b) {
    const double seconds = std::max(kMinMoveS, angle_deg(a, b) / kSpeedDegPerS);
    const long n = std::max(2L, std::lround(seconds / dt_));
    for (long k = 1; k < n; ++k) sample(along(a, b, (1 - std::cos(M_PI * static_cast<double>(k) / n)) / 2), 0);
  }

 private:
  RehearsalResult& r_;
  const Meter& meter_;
  GaussianSource& noise_;
  double dt_;
};

// The rows of the log, counted as LogWriter writes them: each rest and each move (a swing away and
// back between near positions), in double so that no request overflows the count.
struct RowCount {
  double rows = 0;
  void rest(double rate, double seconds) { rows += std::max(1.0, std::round(seconds * rate)); }
  void move(double rate, const Vec3& a, const Vec3& b) {
    rows += std::max(2.0, std::round(std::max(kMinMoveS, angle_deg(a, b) / kSpeedDegPerS) * rate)) - 1;
  }
};

}  // namespace

double rehearsal_rows(const RehearsalRequest& q) {
  RowCount c;
  const auto& p = q.program.positions;
  if (p.empty()) return 0;
  c.rest(q.rate_hz, std::max(q.still_s, q.dwell_s));
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (angle_deg(p[i - 1], p[i]) < kNearDeg) {
      const Vec3 away = along(p[i - 1], perpendicular(p[i - 1]), kSwingDeg / 90.0);
      c.move(q.rate_hz, p[i - 1], away);
      c.move(q.rate_hz, away, p[i]);
    } else {
      c.move(q.rate_hz, p[i - 1], p[i]);
    }
    c.rest(q.rate_hz, q.dwell_s);
  }
  return c.rows;
}

void check_rehearsal_rate(double rate_hz) {
  if (!(rate_hz >= kMinRateHz && rate_hz <= kMaxRateHz))
    throw UsageError(words("{rate} ") + shortest_text(rate_hz) + ": the rehearsal takes " + shortest_text(kMinRateHz) +
                     " to " + shortest_text(kMaxRateHz) +
                     " samples per second (time stamps are written in microseconds)");
}

void check_rehearsal_size(const RehearsalRequest& q) {
  check_rehearsal_rate(q.rate_hz);
  if (q.tumble_s > 0) return;  // a tumbling log's rows are --rate x --tumble (simulate checks them)
  if (const double rows = rehearsal_rows(q); rows > kMaxRehearsalRows)
    throw UsageError(words("{rate} ") + shortest_text(q.rate_hz) + words(" with {dwell} ") + shortest_text(q.dwell_s) +
                     words(" and {still} ") + shortest_text(q.still_s) + " on " + std::to_string(q.program.size()) +
                     " positions asks for " + shortest_text(rows) +
                     " rows, the moves between positions included; the bound is " + shortest_text(kMaxRehearsalRows) +
                     " rows");
}

Meter rehearsal_meter(const RehearsalRequest& q, GaussianSource& gauss) {
  Meter meter;
  if (!q.meter_file.empty()) {
    meter = meter_from_file(q);
  } else {
    Vec9 X;
    for (int k = 0; k < 9; ++k) X(k) = q.size * gauss();
    meter = Meter::from_parameters(X, q.magnitude);
  }
  const Mat3 gain = meter.gain();
  if (!gain.allFinite() || std::abs(gain.determinant()) < 1e-6)
    throw UsageError("the meter's axes are degenerate (non-orthogonality or scale deviations too large)");
  return meter;
}

RehearsalResult rehearse(const RehearsalRequest& q) {
  check_rehearsal_size(q);
  if (q.tumble_s > 0) return rehearse_tumbling(q);
  RehearsalResult r;
  r.request = q;
  GaussianSource gauss(q.seed);
  r.meter = rehearsal_meter(q, gauss);
  r.correction = correction_of(r.meter);
  LogWriter log(r, r.meter, gauss);
  const auto rows = static_cast<std::size_t>(rehearsal_rows(q));
  r.t.reserve(rows);
  r.samples.reserve(rows);
  r.position.reserve(rows);
  const auto& p = q.program.positions;
  log.rest(p[0], std::max(q.still_s, q.dwell_s), 1);
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (angle_deg(p[i - 1], p[i]) < kNearDeg) {
      const Vec3 away = along(p[i - 1], perpendicular(p[i - 1]), kSwingDeg / 90.0);
      log.move(p[i - 1], away);
      log.move(away, p[i]);
    } else {
      log.move(p[i - 1], p[i]);
    }
    log.rest(p[i], q.dwell_s, static_cast<int>(i + 1));
  }
  // Every number written is finite: a magnitude near the largest double overflows once the meter's
  // gain and noise are applied.
  for (const Vec3& s : r.samples)
    if (!s.allFinite())
      throw UsageError(words("{magnitude} ") + shortest_text(q.magnitude) +
                       ": the meter's outputs overflow double precision; give |I| in smaller units");
  return r;
}

Json truth_json(const RehearsalResult& r) {
  const auto triple = [](const Vec3& v) { return Json{v(0), v(1), v(2)}; };
  const Mat3& m = r.correction.matrix;
  Json j{{"bias", triple(r.meter.bias)},
         {"scale_deviation", triple(r.meter.scale_deviation)},
         {"nonorthogonality", triple(r.meter.nonorthogonality())},
         {"offset", triple(r.correction.offset)},
         {"matrix", Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}},
         {"magnitude", r.request.magnitude},
         {"noise", r.request.noise * r.request.magnitude},
         {"seed", r.request.seed},
         {"program", r.request.name},
         {"positions", r.request.program.size()},
         {"rows", r.t.size()}};
  if (r.request.tumble_s > 0) {
    Json disturbed = Json::array();
    for (const auto& [start, end] : r.disturbed) disturbed.push_back(Json{{"start", start}, {"end", end}});
    j["instrument"] = r.request.accelerometer ? "accel" : "mag";
    j["tumble_s"] = r.request.tumble_s;
    j["disturbed"] = disturbed;
  }
  return j;
}

void write_raw_log(std::ostream& out, const RehearsalResult& r, bool text_format, const std::string& file) {
  const RehearsalRequest& q = r.request;
  // The text form is IMU-TK's: numbers only (its reader takes no comment line); what the CSV's
  // comments say is in the truth file.
  if (!text_format) {
    if (!q.region.empty()) out << region_line(specs_written_to(q.region, file));
    out << "# rehearsal of " << display_name(q.name) << " (scalcal simulate, seed " << q.seed
        << "): " << q.program.size() << " positions, " << q.rate_hz << " Hz\n";
    out << "t,ix,iy,iz\n";
  }
  const char sep = text_format ? ' ' : ',';
  char line[160];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const Vec3& s = r.samples[i];
    const int n =
        std::snprintf(line, sizeof line, "%.6f%c%.12g%c%.12g%c%.12g\n", r.t[i], sep, s(0), sep, s(1), sep, s(2));
    // check_rehearsal_size keeps t below 1e11 s (24 characters): a row that does not fit is a bug.
    if (n < 0 || n >= static_cast<int>(sizeof line)) throw std::logic_error("a rehearsal row longer than its buffer");
    out << line;
  }
}

void write_bench_file(std::ostream& out, const RehearsalResult& r, const std::string& file) {
  const RehearsalRequest& q = r.request;
  if (!q.region.empty()) out << region_line(specs_written_to(q.region, file));
  out << "# rehearsal of " << display_name(q.name) << " (scalcal simulate, seed " << q.seed << ")\n";
  out << "position,x,y,z,ix,iy,iz\n";
  char line[256];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    if (r.position[i] == 0) continue;
    const Vec3& x = q.program.positions[static_cast<std::size_t>(r.position[i] - 1)];
    const Vec3& s = r.samples[i];
    const int n = std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.12g,%.12g,%.12g\n", r.position[i], x(0),
                                x(1), x(2), s(0), s(1), s(2));
    if (n < 0 || n >= static_cast<int>(sizeof line)) throw std::logic_error("a bench-file row longer than its buffer");
    out << line;
  }
}

}  // namespace scalcal::commands
