// One window length's moving variance and quiet floor over a log stream (moving_variance.hpp).
#include "numeric/calibration/moving_variance.hpp"

#include <algorithm>
#include <cmath>

namespace scalcal {
namespace {

// The noise floor from the windows: the median of the quiet ones, those below 3 times the 5 %
// quantile of all windows' variance norms. A quantised quiet output can make most quiet windows
// exactly zero: the positive ones set the floor then.
double quiet_floor_of(std::vector<double> v) {
  const auto quantile = [](std::vector<double>& x, double q) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(x.size() - 1));
    std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(k), x.end());
    return x[k];
  };
  double low = quantile(v, 0.05);
  if (!(low > 0)) {
    std::vector<double> positive;
    for (double x : v)
      if (x > 0) positive.push_back(x);
    if (positive.empty()) return 0;
    v = positive;
    low = quantile(v, 0.05);
  }
  std::vector<double> quiet;
  for (double x : v)
    if (x <= 3 * low) quiet.push_back(x);
  return quantile(quiet, 0.5);
}

}  // namespace

MovingVariance::MovingVariance(double window_seconds, bool quiet_floor)
    : window_seconds_(window_seconds), quiet_floor_(quiet_floor) {}

void MovingVariance::advance(const LogStream& stream) {
  if (!fix_window(stream)) return;
  extend(stream);
  if (quiet_floor_) update_floor(stream);
}

// The window in samples, once the stream's period is fixed: window_seconds of samples, at least
// 11, odd, at most the log so far (which only binds on a log shorter than one window).
bool MovingVariance::fix_window(const LogStream& stream) {
  if (window_ > 0) return true;
  const double period = stream.period_for(window_seconds_);
  if (!(period > 0)) return false;
  const int n = stream.log().size();
  if (!stream.ended() && static_cast<double>(n) < window_seconds_ / period) return false;  // a window's span yet
  // In doubles first: a log whose time steps are tiny would overflow an int.
  const double window = std::clamp(window_seconds_ / period, 11.0, static_cast<double>(std::max(n, 11)));
  window_ = std::max(11, static_cast<int>(std::lround(window)) | 1);
  return true;
}

void MovingVariance::extend(const LogStream& stream) {
  const int h = window_ / 2, n = stream.log().size();
  const int upto = stream.ended() ? n : stream.decided() - h;
  for (int i = static_cast<int>(variances_.size()); i < upto; ++i) {
    const double v = i + h < stream.decided() ? stream.window_variance(i, h) : NAN;
    variances_.push_back(v);
    if (!std::isfinite(v)) continue;
    finite_.push_back(v);
    if (stream.window_white(i, h)) ++white_;
  }
}

// The quiet windows' median, recomputed as the windows grow by a sixty-fourth (the whole log at its
// end), and trusted once white windows make up the 5 % of the windows whose quantile it starts from
// (and at least a window's worth): before, the quietest windows could be a slow motion's.
void MovingVariance::update_floor(const LogStream& stream) {
  if (finite_.empty() || finite_.size() == floor_windows_) return;
  const bool trusted = white_ >= kFloorWhiteWindows * window_ && 20.0 * white_ >= static_cast<double>(finite_.size());
  if (!stream.ended() && (!trusted || finite_.size() < floor_windows_ + std::max<std::size_t>(1, floor_windows_ / 64)))
    return;
  floor_ = quiet_floor_of(finite_);
  floor_windows_ = finite_.size();
}

}  // namespace scalcal
