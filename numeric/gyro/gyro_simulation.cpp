// Simulated rate-table, known-turn and hand-rotation logs (gyro_simulation.hpp).
#include "numeric/gyro/gyro_simulation.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "numeric/gyro/rotation_integral.hpp"

namespace scalcal::gyro {
namespace {

constexpr int kFineSteps = 16;  // integration steps per logged sample

// A rotation taking unit vector a onto unit vector b (about a x b; a half turn when opposite).
Mat3 rotation_onto(const Vec3& a, const Vec3& b) {
  const Vec3 c = a.cross(b);
  const double s = c.norm(), co = a.dot(b);
  if (s < 1e-12) {
    if (co > 0) return Mat3::Identity();
    int k = 0;
    a.cwiseAbs().minCoeff(&k);
    return rotation_exp(M_PI * a.cross(Vec3::Unit(k)).normalized());
  }
  return rotation_exp(std::atan2(s, co) * c / s);
}

struct LogWriter {
  SimulatedLog out;
  double period;
  GaussianSource noise;
  const GyroTruth& truth;
  LogWriter(const GyroTruth& t, double rate, std::uint64_t seed) : period(1 / rate), noise(seed), truth(t) {}
  double now() const { return static_cast<double>(out.log.t.size()) * period; }
  void sample(const Vec3& omega, double commanded) {
    Vec3 raw = truth.offset + truth.gain * omega;
    for (int c = 0; c < 3; ++c) raw(c) += truth.noise * noise();
    out.log.lines.push_back(static_cast<int>(out.log.t.size()) + 2);  // a CSV's header is line 1
    out.log.t.push_back(now());
    out.log.samples.push_back(raw);
    out.rate.push_back(commanded);
  }
};

void check_axis(const Vec3& axis) {
  if (!(std::abs(axis.norm() - 1) < 1e-9)) throw std::invalid_argument("a segment's axis must be a unit vector");
}

}  // namespace

SimulatedLog simulate_rate_table(const GyroTruth& truth, const std::vector<TableSegment>& plan,
                                 const RateTableSimulation& o, std::uint64_t seed) {
  LogWriter w(truth, o.sample_rate, seed);
  w.out.log.file = "simulated rate table";
  const double phi = o.latitude_deg * M_PI / 180;
  const Vec3 earth =
      o.earth ? Vec3(kEarthRate * Vec3(0, std::cos(phi), std::sin(phi))) : Vec3::Zero();  // east, north, up
  double angle = 0;                                                                       // the table's angle about up
  // Phase by phase: the rate as a function of the time within it; the mounting for the Earth's term.
  auto run = [&](double seconds, const Mat3& mount, const std::function<double(double)>& rate, double commanded) {
    const double start = w.now();
    const int n = static_cast<int>(std::llround(seconds * o.sample_rate));
    for (int i = 0; i < n; ++i) {
      const double s = w.now() - start;
      const Mat3 to_lab = rotation_exp(angle * Vec3::UnitZ()) * mount;  // meter frame -> laboratory (ENU)
      const Vec3 axis_meter = mount.transpose() * Vec3::UnitZ();
      w.sample(rate(s) * axis_meter + to_lab.transpose() * earth, commanded);
      // The table's angle over the next sample, finely (the rate ramps).
      for (int k = 0; k < kFineSteps; ++k) angle += rate(s + (k + 0.5) * w.period / kFineSteps) * w.period / kFineSteps;
    }
  };
  for (const TableSegment& seg : plan) {
    check_axis(seg.axis);
    if (!(seg.seconds > 0) || !(o.spin_up_seconds >= 0) || !(o.rest_seconds > 0))
      throw std::invalid_argument("durations must be positive");
  }
  Mat3 mount = plan.empty() ? Mat3::Identity() : rotation_onto(plan.front().axis, Vec3::UnitZ());
  run(
      o.rest_seconds, mount, [](double) { return 0.0; }, 0);
  for (const TableSegment& seg : plan) {
    mount = rotation_onto(seg.axis, Vec3::UnitZ());
    const double r = seg.rate, up = o.spin_up_seconds;
    if (up > 0)
      run(
          up, mount, [r, up](double s) { return r * s / up; }, 0);
    run(
        seg.seconds, mount, [r](double) { return r; }, r);
    if (up > 0)
      run(
          up, mount, [r, up](double s) { return r * (1 - s / up); }, 0);
    run(
        o.rest_seconds, mount, [](double) { return 0.0; }, 0);
  }
  return w.out;
}

SimulatedLog simulate_known_turns(const GyroTruth& truth, const std::vector<KnownTurn>& turns, double sample_rate,
                                  double rest_seconds, std::uint64_t seed) {
  LogWriter w(truth, sample_rate, seed);
  w.out.log.file = "simulated known turns";
  auto rest = [&] {
    const int n = static_cast<int>(std::llround(rest_seconds * sample_rate));
    for (int i = 0; i < n; ++i) w.sample(Vec3::Zero(), 0);
  };
  rest();
  for (const KnownTurn& turn : turns) {
    check_axis(turn.axis);
    if (!(turn.seconds > 0)) throw std::invalid_argument("a turn's duration must be positive");
    // angle (1 - cos(pi s / T)) / 2: smooth start and stop, the whole angle by T.
    const int n = static_cast<int>(std::llround(turn.seconds * sample_rate));
    const double start = w.now();
    for (int i = 0; i < n; ++i) {
      const double s = w.now() - start;
      w.sample(turn.angle * M_PI / (2 * turn.seconds) * std::sin(M_PI * s / turn.seconds) * turn.axis, 0);
    }
    rest();
  }
  w.out.rate.clear();
  return w.out;
}

HandRotationLogs simulate_hand_rotations(const GyroTruth& truth, const HandRotationSimulation& o, std::uint64_t seed) {
  GaussianSource draw(seed);  // the motions and the durations
  LogWriter gyro(truth, o.sample_rate, seed ^ 0x9e3779b97f4a7c15ull);
  GaussianSource acc_noise(seed ^ 0x51ed270b27c1a9f3ull);
  HandRotationLogs out;
  Mat3 R = Mat3::Identity();  // body (physical frame) -> world, z up
  auto sample = [&](const Vec3& omega) {
    const Vec3 f = R.transpose() * Vec3(0, 0, o.gravity);  // specific force at rest or turning in place
    Vec3 a = o.accelerometer.measure(f);
    for (int c = 0; c < 3; ++c) a(c) += o.accelerometer_noise * acc_noise();
    out.accelerometer.t.push_back(gyro.now());
    out.accelerometer.samples.push_back(a);
    out.accelerometer.lines.push_back(static_cast<int>(out.accelerometer.lines.size()) + 1);
    gyro.sample(omega, 0);
  };
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * draw.sampler().uniform(); };
  for (int pose = 0; pose < o.poses; ++pose) {
    const int rest = static_cast<int>(std::llround(uniform(o.min_rest_seconds, o.max_rest_seconds) * o.sample_rate));
    for (int i = 0; i < rest; ++i) sample(Vec3::Zero());
    if (pose + 1 == o.poses) break;
    // A motion: a turn of 60-150 degrees about a random axis with a wobble about a perpendicular one
    // (up to 30 degrees and back), both smooth, so the rate's direction changes during the motion.
    const Vec3 a = draw.sampler()() * uniform(M_PI / 3, 5 * M_PI / 6);
    Vec3 b = draw.sampler()();
    b = (b - b.dot(a.normalized()) * a.normalized()).normalized() * uniform(0, M_PI / 6);
    const double T = uniform(o.min_motion_seconds, o.max_motion_seconds);
    auto omega = [&](double s) {
      return Vec3(M_PI / (2 * T) * std::sin(M_PI * s / T) * a + M_PI / T * std::sin(2 * M_PI * s / T) * b);
    };
    const int n = static_cast<int>(std::llround(T * o.sample_rate));
    for (int i = 0; i < n; ++i) {
      const double s = i * gyro.period;
      sample(omega(s));
      const double h = gyro.period / kFineSteps;
      for (int k = 0; k < kFineSteps; ++k) R = R * rotation_exp(omega(s + (k + 0.5) * h) * h);
    }
  }
  out.gyro = gyro.out.log;
  out.gyro.file = "simulated gyro";
  out.accelerometer.file = "simulated accelerometer";
  return out;
}

HandRotationLogs simulate_hand_rotations_through(const GyroTruth& truth, const std::vector<Vec3>& directions,
                                                 const HandRotationSimulation& o, std::uint64_t seed) {
  GaussianSource draw(seed);
  LogWriter gyro(truth, o.sample_rate, seed ^ 0x9e3779b97f4a7c15ull);
  GaussianSource acc_noise(seed ^ 0x51ed270b27c1a9f3ull);
  HandRotationLogs out;
  if (directions.empty()) return out;
  for (const Vec3& d : directions) check_axis(d);
  // The first pose: gravity (world z) along directions[0] in the body: R^T z = eta_0.
  Mat3 R = rotation_onto(directions[0], Vec3::UnitZ());
  auto sample = [&](const Vec3& omega) {
    Vec3 a = o.accelerometer.measure(R.transpose() * Vec3(0, 0, o.gravity));
    for (int c = 0; c < 3; ++c) a(c) += o.accelerometer_noise * acc_noise();
    out.accelerometer.t.push_back(gyro.now());
    out.accelerometer.samples.push_back(a);
    out.accelerometer.lines.push_back(static_cast<int>(out.accelerometer.lines.size()) + 2);
    gyro.sample(omega, 0);
  };
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * draw.sampler().uniform(); };
  // One phase: a body-frame rotation vector v over T seconds, smooth start and stop.
  auto turn = [&](const Vec3& v, double T) {
    const int n = std::max(1, static_cast<int>(std::llround(T * o.sample_rate)));
    const double dt = gyro.period;
    for (int i = 0; i < n; ++i) {
      const double s = i * dt;
      auto omega = [&](double u) { return Vec3(M_PI / (2 * T) * std::sin(M_PI * std::min(u, T) / T) * v); };
      sample(omega(s));
      const double h = dt / kFineSteps;
      for (int k = 0; k < kFineSteps; ++k) R = R * rotation_exp(omega(s + (k + 0.5) * h) * h);
    }
  };
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const int rest = static_cast<int>(std::llround(uniform(o.min_rest_seconds, o.max_rest_seconds) * o.sample_rate));
    for (int i = 0; i < rest; ++i) sample(Vec3::Zero());
    if (k + 1 == directions.size()) break;
    const double T = uniform(o.min_motion_seconds, o.max_motion_seconds);
    const Vec3 g = R.transpose() * Vec3::UnitZ();  // gravity in the body now (the last phase's end)
    turn(uniform(-M_PI / 3, M_PI / 3) * g, T / 2);
    // The tilt: exp(theta a) g = next, a = g x next / |g x next|, done as the body rate -theta a.
    const Vec3 next = directions[k + 1], c = g.cross(next);
    const double theta = std::atan2(c.norm(), g.dot(next));
    Vec3 a = c.norm() > 1e-12 ? Vec3(c / c.norm()) : Vec3(g.unitOrthogonal());
    turn(-theta * a, T / 2);
  }
  out.gyro = gyro.out.log;
  out.gyro.file = "simulated gyro";
  out.accelerometer.file = "simulated accelerometer";
  return out;
}

GyroTruth reference_gyro(bool rotated) {
  Meter m;
  m.scale_deviation = Vec3(0.003, -0.002, 0.001);
  m.misalignment << 0, 0.002, 0.0015, 0.002, 0, -0.003, 0.0015, -0.003, 0;
  GyroTruth t;
  t.gain = 4780.0 * m.gain();
  if (rotated) t.gain = t.gain * rotation_exp(Vec3(0.01, -0.02, 0.015)).transpose();
  t.offset = Vec3(32777, 32460, 32512);
  t.noise = 27;
  return t;
}

}  // namespace scalcal::gyro
