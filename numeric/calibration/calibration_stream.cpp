// Calibration as a stream: the log's stage and every detector fed chunk by chunk (calibration_stream.hpp).
#include "numeric/calibration/calibration_stream.hpp"

#include <algorithm>
#include <memory>

namespace scalcal {

CalibrationStream::CalibrationStream(std::string file, const StaticIntervalOptions& options, bool adaptive)
    : stream_(std::move(file)) {
  if (!adaptive) {
    detectors_.emplace_back(options);
    return;
  }
  // One moving variance per window length, shared by the detectors of that window (exact: theirs
  // were the same numbers computed again; 4 windows for 37 detectors).
  std::vector<std::shared_ptr<MovingVariance>> windows;
  for (const StaticIntervalOptions& o : detection_candidates(options)) {
    const bool quiet_floor = !(o.still_seconds > 0);  // a floor from --still needs no quiet windows' floor
    auto shared = std::find_if(windows.begin(), windows.end(), [&](const auto& w) {
      return w->window_seconds() == o.window_seconds && w->quiet_floor() == quiet_floor;
    });
    if (shared == windows.end())
      shared = windows.insert(windows.end(), std::make_shared<MovingVariance>(o.window_seconds, quiet_floor));
    detectors_.emplace_back(o, *shared);
  }
}

void CalibrationStream::add(const RawLog& chunk, bool last) {
  stream_.add(chunk, last);
  advance();
}

void CalibrationStream::add(RawLog&& chunk, bool last) {
  stream_.add(std::move(chunk), last);
  advance();
}

void CalibrationStream::advance() {
  for (StillPoseDetector& d : detectors_) d.advance(stream_);
  ++chunks_;
}

std::vector<PoseSums> CalibrationStream::pose_sums() const {
  const RawLog& log = stream_.log();
  std::vector<PoseSums> out;
  for (const StaticInterval& iv : detectors_.front().detection(stream_).intervals) {
    PoseSums p;
    p.begin = iv.begin;
    p.end = iv.end;
    Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
    const Vec3 shift = log.samples[static_cast<std::size_t>(iv.begin)];
    for (int i = iv.begin; i <= iv.end; ++i) {
      if (!stream_.usable()[static_cast<std::size_t>(i)] || iv.in_break(i)) continue;
      const Vec3 s = log.samples[static_cast<std::size_t>(i)] - shift;
      sum += s;
      sum2 += s.cwiseProduct(s);
      ++p.samples;
    }
    const Vec3 m = sum / std::max(p.samples, 1);
    p.mean = shift + m;
    p.variance = (sum2 / std::max(p.samples, 1) - m.cwiseProduct(m)).cwiseMax(0.0);
    out.push_back(p);
  }
  return out;
}

std::optional<DetectionChoice> CalibrationStream::choose(
    const std::function<std::optional<double>(const IntervalDetection&)>& score) const {
  if (detectors_.size() == 1) return std::nullopt;
  return choose_detection(
      [&](const StaticIntervalOptions&, int k) { return detectors_[static_cast<std::size_t>(k)].detection(stream_); },
      detectors_.front().options(), score);
}

}  // namespace scalcal
