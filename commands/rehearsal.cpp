// Rehearsal logs (rehearsal.hpp).
#include "commands/rehearsal.hpp"

#include <cmath>
#include <cstdio>

#include "commands/tumbling_rehearsal.hpp"
#include "commands/usage_error.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"

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

}  // namespace

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
  if (q.tumble_s > 0) return rehearse_tumbling(q);
  RehearsalResult r;
  r.request = q;
  GaussianSource gauss(q.seed);
  r.meter = rehearsal_meter(q, gauss);
  r.correction = correction_of(r.meter);
  LogWriter log(r, r.meter, gauss);
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

void write_raw_log(std::ostream& out, const RehearsalResult& r, bool text_format) {
  const RehearsalRequest& q = r.request;
  // The text form is IMU-TK's: numbers only (its reader takes no comment line); what the CSV's
  // comments say is in the truth file.
  if (!text_format) {
    if (!q.region.empty()) {
      out << "# region: ";
      for (std::size_t k = 0; k < q.region.size(); ++k) out << (k ? ";" : "") << q.region[k];
      out << "\n";
    }
    out << "# rehearsal of " << display_name(q.name) << " (scalcal simulate, seed " << q.seed
        << "): " << q.program.size() << " positions, " << q.rate_hz << " Hz\n";
    out << "t,ix,iy,iz\n";
  }
  const char sep = text_format ? ' ' : ',';
  char line[160];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const Vec3& s = r.samples[i];
    std::snprintf(line, sizeof line, "%.6f%c%.12g%c%.12g%c%.12g\n", r.t[i], sep, s(0), sep, s(1), sep, s(2));
    out << line;
  }
}

void write_bench_file(std::ostream& out, const RehearsalResult& r) {
  const RehearsalRequest& q = r.request;
  if (!q.region.empty()) {
    out << "# region: ";
    for (std::size_t k = 0; k < q.region.size(); ++k) out << (k ? ";" : "") << q.region[k];
    out << "\n";
  }
  out << "# rehearsal of " << display_name(q.name) << " (scalcal simulate, seed " << q.seed << ")\n";
  out << "position,x,y,z,ix,iy,iz\n";
  char line[256];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    if (r.position[i] == 0) continue;
    const Vec3& x = q.program.positions[static_cast<std::size_t>(r.position[i] - 1)];
    const Vec3& s = r.samples[i];
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.12g,%.12g,%.12g\n", r.position[i], x(0), x(1), x(2), s(0),
                  s(1), s(2));
    out << line;
  }
}

}  // namespace scalcal::commands
