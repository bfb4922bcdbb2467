// Calibration as a stream: a raw log's samples taken in chunks (a serial port's, a logger's), still
// poses found as they settle by the stream's detector (pose_stream.hpp), with its own options and,
// where they are not given, every candidate of the adaptive choice (adaptive_detection.hpp) beside
// them, and the fit made on request from the poses settled so far. The whole log as one last chunk
// gives the batch calibration's detection and choice, decision for decision; `calibrate` is that.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "numeric/calibration/adaptive_detection.hpp"
#include "numeric/calibration/pose_stream.hpp"

namespace scalcal {

// One settled pose's sums, for a caller that keeps no samples (the mean and scatter of its usable
// samples, raw units).
struct PoseSums {
  int begin = 0, end = 0;  // sample indices, inclusive
  int samples = 0;
  Vec3 mean = Vec3::Zero();
  Vec3 variance = Vec3::Zero();  // per output, over the pose's samples
};

class CalibrationStream {
 public:
  // adaptive: keep the candidates' detectors too (the options were not chosen by the user).
  CalibrationStream(std::string file, const StaticIntervalOptions& options, bool adaptive);
  // Appends a chunk and settles what it allows; `last`: the log ends with it.
  void add(const RawLog& chunk, bool last = false);
  void add(RawLog&& chunk, bool last = false);  // a first chunk becomes the log without a copy
  int chunks() const { return chunks_; }
  const RawLog& log() const { return stream_.log(); }
  RawLog release_log() && { return std::move(stream_).release(); }  // for a caller done with the stream

  // The poses under the given options so far (throws as detect_static_intervals once the log ended).
  IntervalDetection detection() const { return detectors_.front().detection(stream_); }
  std::vector<PoseSums> pose_sums() const;
  // Those poses' samples, for the fit (calibrate_any_units) made on request.
  std::vector<PositionSamples> positions() const { return interval_positions(stream_.log(), detection()); }
  // The candidates' choice among the poses so far, scored as choose_detection scores (empty when the
  // stream is not adaptive or no candidate scores).
  std::optional<DetectionChoice> choose(
      const std::function<std::optional<double>(const IntervalDetection&)>& score) const;

 private:
  void advance();  // the detectors over the rows just taken

  LogStream stream_;
  std::vector<StillPoseDetector> detectors_;  // the options', then the candidates' in choose_detection's order
  int chunks_ = 0;
};

}  // namespace scalcal
