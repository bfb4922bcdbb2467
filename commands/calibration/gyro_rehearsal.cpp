// A gyro's rehearsal (gyro_rehearsal.hpp).
#include "commands/calibration/gyro_rehearsal.hpp"

#include <cmath>

#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/calibration/full_correction.hpp"
#include "numeric/gyro/rotation_integral.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }
Json rows_of(const Mat3& m) { return Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}; }

// A meter with N(0, size^2) errors (bias relative to |I|), the accelerometer rehearsal's way.
Meter random_meter(GaussianSource& draw, double size, double magnitude) {
  Meter m;
  for (int k = 0; k < 3; ++k) m.bias(k) = size * draw() * magnitude;
  for (int k = 0; k < 3; ++k) m.scale_deviation(k) = size * draw();
  Vec9 X;
  X << m.bias / magnitude, m.scale_deviation, size * draw(), size * draw(), size * draw();
  return Meter::from_parameters(X, magnitude);
}

// Rate-table segments from a program: a position whose antipode came earlier is that mounting turned
// the other way (no remount), any other a mounting of its own.
std::vector<gyro::TableSegment> table_plan(const Program& p, double rate, double seconds) {
  std::vector<gyro::TableSegment> out;
  for (const Vec3& eta : p.positions) {
    gyro::TableSegment s{eta, rate, seconds};
    for (const auto& earlier : out)
      if ((earlier.axis + eta).norm() < 1e-9 && earlier.rate > 0) s = {earlier.axis, -rate, seconds};
    out.push_back(s);
  }
  return out;
}

}  // namespace

GyroRehearsalResult rehearse_gyro(const GyroRehearsalRequest& q) {
  GyroRehearsalResult r;
  r.request = q;
  GaussianSource draw(q.seed ^ 0x2545f4914f6cdd1dull);
  const bool hand = q.method == "hand_rotations";
  const double magnitude = hand ? 1.0 : q.magnitude;
  const Meter m = random_meter(draw, q.size, magnitude);
  r.truth.gain = m.gain();
  if (hand) r.truth.gain = r.truth.gain * gyro::rotation_exp(q.size * Vec3(draw(), draw(), draw()));
  r.truth.offset = m.bias;
  r.truth.noise = q.noise * magnitude;
  Program program = q.program;
  for (Vec3& p : program.positions) p.normalize();
  if (q.method == "rate_table") {
    gyro::RateTableSimulation o;
    o.sample_rate = q.rate_hz;
    o.rest_seconds = std::max(2.0, q.dwell_s / 2);
    o.earth = q.latitude_deg.has_value();
    if (q.latitude_deg) o.latitude_deg = *q.latitude_deg;
    r.log = gyro::simulate_rate_table(r.truth, table_plan(program, q.magnitude, q.dwell_s), o, q.seed);
  } else if (q.method == "known_turns") {
    std::vector<gyro::KnownTurn> turns;
    const double angle = q.turn_angle_deg * M_PI / 180;
    for (const Vec3& eta : program.positions)
      turns.push_back({eta, angle, std::max(2.0, std::abs(angle) / (M_PI / 2))});
    r.log = gyro::simulate_known_turns(r.truth, turns, q.rate_hz, q.dwell_s, q.seed);
  } else {
    gyro::HandRotationSimulation o;
    o.sample_rate = q.rate_hz;
    o.gravity = 9.80665;
    r.accelerometer = random_meter(draw, q.size, o.gravity);
    o.accelerometer = r.accelerometer;
    o.accelerometer_noise = q.noise * o.gravity;
    o.min_rest_seconds = o.max_rest_seconds = q.dwell_s;
    const gyro::HandRotationLogs logs = gyro::simulate_hand_rotations_through(r.truth, program.positions, o, q.seed);
    r.log.log = logs.gyro;
    r.accelerometer_log = logs.accelerometer;
  }
  // Every number written is finite (as the accelerometer's rehearsal checks): a rate near the largest
  // double overflows once the gain and noise are applied.
  for (const Vec3& s : r.log.log.samples)
    if (!s.allFinite())
      throw UsageError(words("{magnitude} ") + shortest_text(q.magnitude) +
                       ": the gyro's outputs overflow double precision; give the rate in smaller units");
  return r;
}

Json gyro_truth_json(const GyroRehearsalResult& r) {
  const auto& q = r.request;
  const Mat3 C = r.truth.correction();
  Json j{{"instrument", "gyro"},
         {"method", q.method},
         {"offset", triple(r.truth.offset)},
         {"matrix", rows_of(C)},
         {"noise", r.truth.noise},
         {"seed", q.seed},
         {"program", q.name},
         {"positions", q.program.size()},
         {"rows", r.log.log.size()}};
  if (const auto c = canonical_correction(C, r.truth.offset)) {
    j["bias"] = triple(c->offset);
    j["scale"] = triple(c->scale);
    j["nonorthogonality"] = triple(c->nonorthogonality);
  }
  if (q.method != "hand_rotations") j["magnitude"] = q.magnitude;
  if (q.method == "known_turns") j["turn_angle_deg"] = q.turn_angle_deg;
  if (q.latitude_deg) j["latitude_deg"] = *q.latitude_deg;
  if (r.accelerometer_log) {
    const FullCorrection a = correction_of(r.accelerometer);
    j["accelerometer"] = Json{{"offset", triple(a.offset)}, {"matrix", rows_of(a.matrix)}, {"magnitude", 9.80665}};
  }
  return j;
}

void write_gyro_log(std::ostream& out, const RawLog& log, const std::vector<double>& rate) {
  const bool with_rate = !rate.empty();
  out << "t,ix,iy,iz" << (with_rate ? ",rate" : "") << "\n";
  for (int i = 0; i < log.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    out << shortest_text(log.t[k]) << ',' << shortest_text(log.samples[k](0)) << ',' << shortest_text(log.samples[k](1))
        << ',' << shortest_text(log.samples[k](2));
    if (with_rate) out << ',' << shortest_text(rate[k]);
    out << '\n';
  }
}

}  // namespace scalcal::commands
