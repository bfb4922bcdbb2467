// Calibration as a stream (issue 51): a simulated log whose still segments are known, given in
// chunks of every size, against the truth (each segment found once, inside its true span), the
// floor against the noise the simulator put in, a log that starts in motion, saturation across a
// chunk's edge, and what a stream refuses.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/calibration_stream.hpp"
#include "numeric/io/input_error.hpp"
#include "tests/calibration/raw_log_simulator.hpp"

namespace scalcal {
namespace {

using namespace calibration_test;

RawLog rows(const RawLog& log, int begin, int end) {
  RawLog c;
  c.file = log.file;
  c.t.assign(log.t.begin() + begin, log.t.begin() + end);
  c.samples.assign(log.samples.begin() + begin, log.samples.begin() + end);
  c.lines.assign(log.lines.begin() + begin, log.lines.begin() + end);
  return c;
}

CalibrationStream streamed(const RawLog& log, int chunk, const StaticIntervalOptions& o = {}) {
  CalibrationStream s(log.file, o, false);
  for (int b = 0; b < log.size(); b += chunk)
    s.add(rows(log, b, std::min(log.size(), b + chunk)), b + chunk >= log.size());
  return s;
}

// Each true still segment holds exactly one interval, inside it and covering all but its edges.
void expect_segments(const IntervalDetection& d, const std::vector<StillSegment>& still, double window_s) {
  ASSERT_EQ(d.intervals.size(), still.size());
  for (std::size_t k = 0; k < still.size(); ++k) {
    EXPECT_GE(d.intervals[k].start, still[k].start - 1e-9) << k;
    EXPECT_LE(d.intervals[k].stop, still[k].end + 1e-9) << k;
    EXPECT_GT(d.intervals[k].stop - d.intervals[k].start, (still[k].end - still[k].start) - 1.2 * window_s) << k;
  }
}

TEST(PoseStream, ChunksOfEverySizeFindTheKnownSegments) {
  LogSpec spec;
  spec.lead_motion = 20;  // no still start: the floor must not come from the motion
  const SimulatedLog sim = simulate_log(spec, fourteen_directions());
  const RawLog log = parse_raw_log(sim.text, "simulated.txt");
  // A still window's variance norm is sqrt(3) sigma^2 over three equal variances, less its
  // (w - 1) / w bias; the quantum of 1 count adds 1/12 per output.
  const double sigma2 = spec.noise * spec.noise + 1.0 / 12, truth = std::sqrt(3.0) * sigma2 * 100 / 101;
  for (int chunk : {1, 7, 100, 4096, log.size()}) {
    const CalibrationStream s = streamed(log, chunk);
    const IntervalDetection d = s.detection();
    expect_segments(d, sim.still, 1.0);
    EXPECT_NEAR(d.still_variance / truth, 1, 0.1) << chunk;
    EXPECT_EQ(d.window, 101) << chunk;
  }
}

// A log that starts with 30 s of slow motion into its first pose (60 degrees at 2 degrees per second):
// with the first windows all motion, a floor taken from them would be the motion's, its threshold
// would take the motion for a pose and the first pose would be lost in a run that turns. The stream
// waits for white windows to make up the floor's 5 %.
RawLog settling_start(const LogSpec& spec, std::vector<StillSegment>& still) {
  const SimulatedLog sim = simulate_log(spec, fourteen_directions());
  const RawLog rest = parse_raw_log(sim.text, "settling.txt");
  RawLog log;
  log.file = "settling.txt";
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, spec.noise);
  const double lead = 30, dt = 1 / spec.rate, deg = 3.14159265358979 / 180;
  const int n = static_cast<int>(lead * spec.rate);
  for (int i = 0; i < n; ++i) {
    const double a = 60 * deg * (1 - static_cast<double>(i) / n);  // angle from the first pose
    const V3 d{std::sin(a), 0, std::cos(a)};  // turning onto the first direction, (1, 0, 0) rotated: x <-> z
    const V3 first = unit(fourteen_directions()[0]);
    const V3 dir{first[0] * d[2], d[0], 0};
    Vec3 raw;
    for (int c = 0; c < 3; ++c)
      raw(c) =
          std::round(spec.zero + spec.counts_per_unit * spec.magnitude * dir[static_cast<std::size_t>(c)] + gauss(rng));
    log.t.push_back(i * dt);
    log.samples.push_back(raw);
    log.lines.push_back(i + 1);
  }
  for (int i = 0; i < rest.size(); ++i) {
    log.t.push_back(lead + rest.t[static_cast<std::size_t>(i)]);
    log.samples.push_back(rest.samples[static_cast<std::size_t>(i)]);
    log.lines.push_back(n + rest.lines[static_cast<std::size_t>(i)]);
  }
  still = sim.still;
  for (auto& seg : still) seg.start += lead, seg.end += lead;
  return log;
}

TEST(PoseStream, ASlowStartIsNotTakenForTheFloor) {
  LogSpec spec;
  std::vector<StillSegment> still;
  const RawLog log = settling_start(spec, still);
  for (int chunk : {10, 1000, log.size()}) {
    const IntervalDetection d = streamed(log, chunk).detection();
    expect_segments(d, still, 1.0);
  }
}

// Asking for the poses between chunks changes nothing the stream decides (a question must not fix
// the period or the floor early).
TEST(PoseStream, AskingDoesNotChangeTheAnswer) {
  LogSpec spec;
  spec.lead_motion = 20;
  RawLog log = parse_raw_log(simulate_log(spec, fourteen_directions()).text, "simulated.txt");
  for (int i = 0; i < log.size(); ++i)  // a logger's jitter: the median step of a few rows is not the log's
    log.t[static_cast<std::size_t>(i)] += 2e-4 * std::sin(1.7 * i);
  for (bool adaptive : {false, true}) {
    CalibrationStream asked(log.file, {}, adaptive), quiet(log.file, {}, adaptive);
    for (int b = 0; b < log.size(); b += 7) {
      const RawLog part = rows(log, b, std::min(log.size(), b + 7));
      asked.add(part, b + 7 >= log.size());
      quiet.add(part, b + 7 >= log.size());
      (void)asked.detection();
      (void)asked.pose_sums();
    }
    const IntervalDetection a = asked.detection(), q = quiet.detection();
    ASSERT_EQ(a.intervals.size(), q.intervals.size());
    for (std::size_t k = 0; k < a.intervals.size(); ++k) {
      EXPECT_EQ(a.intervals[k].begin, q.intervals[k].begin);
      EXPECT_EQ(a.intervals[k].end, q.intervals[k].end);
    }
    EXPECT_EQ(a.still_variance, q.still_variance);
    EXPECT_EQ(a.sample_period, q.sample_period);
  }
}

// The fit on request: half the log gives the poses settled in it, and the calibration of the whole
// stream recovers the simulated meter within its standard errors.
TEST(PoseStream, TheFitIsMadeFromThePosesSettledSoFar) {
  LogSpec spec;
  spec.meter = example_meter(0.01, spec.magnitude);
  const SimulatedLog sim = simulate_log(spec, fourteen_directions());
  const RawLog log = parse_raw_log(sim.text, "simulated.txt");
  CalibrationStream s(log.file, {}, false);
  const int half = log.size() / 2;
  s.add(rows(log, 0, half));
  const std::size_t early = s.detection().intervals.size();
  int before_half = 0;
  for (const auto& seg : sim.still) before_half += seg.end + 1.5 < log.t[static_cast<std::size_t>(half)];
  EXPECT_GE(static_cast<int>(early), before_half - 1);
  EXPECT_LE(static_cast<int>(early), before_half);
  s.add(rows(log, half, log.size()), true);
  const std::vector<PositionSamples> positions = s.positions();
  ASSERT_EQ(positions.size(), 14u);
  AnyUnitsOptions o;
  o.magnitude = spec.magnitude;
  const AnyUnitsCalibration a = calibrate_any_units("simulated", positions, o);
  ASSERT_TRUE(a.estimate.summary.converged());
  for (int c = 0; c < 3; ++c)  // raw = zero + counts_per_unit * (bias + ...)
    EXPECT_NEAR(a.correction.offset(c), spec.zero + spec.counts_per_unit * spec.meter.bias[static_cast<std::size_t>(c)],
                6 * a.bias_std(c))
        << c;
  // The sums the stream keeps per pose: each pose's mean is the mean of its samples.
  const std::vector<PoseSums> sums = s.pose_sums();
  ASSERT_EQ(sums.size(), 14u);
  EXPECT_LT((sums[3].mean - positions[3].mean()).norm(), 1e-9 * sums[3].mean.norm());
  EXPECT_EQ(sums[3].samples, static_cast<int>(positions[3].samples.size()));
}

// A clipped output split across two chunks (one row, then two) is still a run of three at the rail.
TEST(PoseStream, SaturationAcrossAChunksEdge) {
  const SimulatedLog sim = simulate_log(LogSpec{}, fourteen_directions());
  RawLog log = parse_raw_log(sim.text, "s.txt");
  for (int i = 7000; i < 7003; ++i) log.samples[static_cast<std::size_t>(i)](0) = 65535;
  CalibrationStream s(log.file, {}, false);
  s.add(rows(log, 0, 7001));
  s.add(rows(log, 7001, 7003));
  s.add(rows(log, 7003, log.size()), true);
  EXPECT_EQ(s.detection().saturated, 3);
}

TEST(PoseStream, RefusesTimeGoingBackAndRowsAfterTheEnd) {
  const SimulatedLog sim = simulate_log(LogSpec{}, fourteen_directions());
  const RawLog log = parse_raw_log(sim.text, "s.txt");
  CalibrationStream s(log.file, {}, false);
  s.add(rows(log, 100, 200));
  EXPECT_THROW(s.add(rows(log, 0, 100)), InputError);
  CalibrationStream ended(log.file, {}, false);
  ended.add(rows(log, 0, 200), true);
  EXPECT_THROW(ended.add(rows(log, 200, 300)), InputError);
}

}  // namespace
}  // namespace scalcal
