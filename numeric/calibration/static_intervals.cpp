// Static positions in a raw log: the stream's detection given the whole log at once (static_intervals.hpp).
#include "numeric/calibration/static_intervals.hpp"

#include <cmath>

#include "numeric/calibration/pose_stream.hpp"

namespace scalcal {

Vec3 window_axis_variances(const Vec3& sum, const Vec3& sum2, int w) {
  const Vec3 m = sum / w;
  return (sum2 / w - m.cwiseProduct(m)).cwiseMax(0.0);
}

double window_variance_norm(const Vec3& sum, const Vec3& sum2, int w) {
  // The norm squares the variances again: beyond 1e150 it is taken scaled (it would overflow),
  // below unchanged (the same bits as always).
  const Vec3 v = window_axis_variances(sum, sum2, w);
  const double largest = v.maxCoeff();
  return largest > 1e150 ? largest * (v / largest).norm() : v.norm();
}

// The variance norm of the window of w samples centred on each sample, by prefix sums (shifted
// by `shift`: raw sums of counts near 32768 would cancel badly); NaN where the window is incomplete
// or holds an unusable sample.
std::vector<double> window_variances(const RawLog& log, const std::vector<char>& usable, int w, const Vec3& shift) {
  const int n = log.size(), h = w / 2;
  std::vector<Vec3> ps(static_cast<std::size_t>(n) + 1, Vec3::Zero()),
      ps2(static_cast<std::size_t>(n) + 1, Vec3::Zero());
  std::vector<int> bad(static_cast<std::size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3 s = usable[k] ? Vec3(log.samples[k] - shift) : Vec3::Zero();
    ps[k + 1] = ps[k] + s;
    ps2[k + 1] = ps2[k] + s.cwiseProduct(s);
    bad[k + 1] = bad[k] + (usable[k] ? 0 : 1);
  }
  std::vector<double> out(static_cast<std::size_t>(n), NAN);
  for (int i = h; i + h < n; ++i) {
    const auto a = static_cast<std::size_t>(i - h), b = static_cast<std::size_t>(i + h + 1);
    if (bad[b] - bad[a] > 0) continue;
    out[static_cast<std::size_t>(i)] = window_variance_norm(ps[b] - ps[a], ps2[b] - ps2[a], w);
  }
  return out;
}

IntervalDetection detect_static_intervals(const RawLog& log, const StaticIntervalOptions& options) {
  LogStream stream(log.file);
  stream.add(log, true);
  StillPoseDetector detector(options);
  detector.advance(stream);
  return detector.detection(stream);
}

}  // namespace scalcal
