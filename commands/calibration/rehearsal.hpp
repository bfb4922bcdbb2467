// A rehearsal of a program (simulate --log, --bench-file): the raw log, or the grouped bench file,
// that a meter with random (or given) parameters would write on the program run in its order, with
// the true parameters beside it in the keys and units of `calibrate --json`, so calibrating the log
// can be checked against what made it.
//
// The log: the meter rests on the first position for max(--still, --dwell) seconds (calibrate's
// still period), then moves to each next position along the great circle between them (a smooth
// cosine profile at about 45 degrees per second, at least one second; between two positions less
// than 5 degrees apart it swings 20 degrees away and back, so the two stay separate intervals) and
// rests there --dwell seconds. The specific force is quasi-static (|I| eta along the path; the
// motion's own accelerations are left out), each output gets white Gaussian noise of --noise |I|.
// The meter (numeric/calibration/meter_model.hpp): raw = bias + (E + dK) Phi (|I| eta), Phi with
// phi_kj = phi_jk (the convention calibrate reports in), random parameters N(0, size^2) each (bias
// relative to |I|) from --seed.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/warning.hpp"
#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/meter_model.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::commands {

struct RehearsalRequest {
  std::string name;                 // the program's name in messages and in the log's comments
  Program program;                  // in run order (a plan file is)
  std::vector<std::string> region;  // the program file's region line, carried into the log
  bool grouped = false;             // the grouped bench file instead of a raw log
  double rate_hz = 100, dwell_s = 5, still_s = 30;
  double noise = 1e-3;     // per output and sample, relative to |I|
  double magnitude = 1;    // |I| in the log's units
  double size = 1e-3;      // scale of a random meter's errors
  std::string meter_file;  // a JSON file with bias, scale_deviation, nonorthogonality ("": random)
  std::uint64_t seed = 1;
  // A tumbling log (tumbling_rehearsal.hpp) instead of still poses: this many seconds of continuous
  // turning (0: none), of a magnetometer (the field keeps its modulus) or an accelerometer (the
  // motion adds acceleration), with this many disturbed stretches (a magnet passing).
  double tumble_s = 0;
  bool accelerometer = false;
  int disturbances = 0;
};

struct RehearsalResult {
  RehearsalRequest request;
  Meter meter;                                       // the truth
  FullCorrection correction;                         // its correction: physical = matrix (raw - offset)
  std::vector<double> t;                             // seconds (the raw log)
  std::vector<Vec3> samples;                         // raw outputs, one per row
  std::vector<int> position;                         // 1-based position of each row, 0 while moving
  std::vector<std::pair<double, double>> rests;      // each position's resting time span (seconds)
  std::vector<std::pair<double, double>> disturbed;  // a tumbling log's disturbed stretches (seconds)
  Warnings warnings;
};

// The work bound of a rehearsal: its rows are counted before any is made (rests and moves alike),
// and its rate is one whose time stamps the log's microseconds resolve.
inline constexpr double kMaxRehearsalRows = 2e7;
inline constexpr double kMinRateHz = 1e-3, kMaxRateHz = 1e6;
double rehearsal_rows(const RehearsalRequest& request);
// Throws UsageError for a rate outside [kMinRateHz, kMaxRateHz] (every rehearsal's, a gyro's too).
void check_rehearsal_rate(double rate_hz);

// Throws UsageError for a rate outside [kMinRateHz, kMaxRateHz] or (a program's rehearsal, not a
// tumbling one) more than kMaxRehearsalRows rows.
void check_rehearsal_size(const RehearsalRequest& request);

// Throws InputError for a meter file that cannot be read or lacks a key, UsageError for a meter
// whose axes are degenerate, a request check_rehearsal_size refuses, or outputs that overflow. A request
// with tumble_s > 0 is a tumbling log's (rehearse_tumbling).
RehearsalResult rehearse(const RehearsalRequest& request);
// The meter of a rehearsal: the file's, or random from the seed's first draws.
Meter rehearsal_meter(const RehearsalRequest& request, GaussianSource& gauss);

// The true parameters: bias (file units), scale_deviation, nonorthogonality (rad), offset, matrix
// (rows; physical = matrix (raw - offset)), magnitude, as calibrate --json has them; with noise
// (file units), seed, program, positions, rows.
Json truth_json(const RehearsalResult& result);

// The raw log: CSV `t,ix,iy,iz` (after the region line and a comment), or text `t ix iy iz` without a
// header (IMU-TK's form). The grouped bench file: CSV `position,x,y,z,ix,iy,iz`, the resting samples
// of each position with its designed direction. `file` is where the text goes ("-": standard output):
// the region line's candidates paths are written as that file's folder sees them.
void write_raw_log(std::ostream& out, const RehearsalResult& result, bool text_format, const std::string& file = "-");
void write_bench_file(std::ostream& out, const RehearsalResult& result, const std::string& file = "-");

}  // namespace scalcal::commands
