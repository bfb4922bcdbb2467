// Still-pose detection as a stream: one detector's state machine over a log stream (pose_stream.hpp).
#include "numeric/calibration/pose_stream.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

std::string seconds(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The noise floor from the windows: the median of the quiet ones, those below 3 times the 5 %
// quantile of all windows' variance norms. A quantised quiet output can make most quiet windows
// exactly zero: the positive ones set the floor then.
double quiet_floor(std::vector<double> v) {
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

// The mean of the usable samples i..j less `shift`, and their count.
Vec3 mean_of(const LogStream& stream, int i, int j, const Vec3& shift, int& count) {
  Vec3 s = Vec3::Zero();
  count = 0;
  for (int k = i; k <= j; ++k)
    if (stream.usable()[static_cast<std::size_t>(k)])
      s += stream.log().samples[static_cast<std::size_t>(k)] - shift, ++count;
  return Vec3(s / std::max(count, 1));
}

// Still runs at most this many samples apart (a second) may be one pose (close_run).
int longest_break(const LogStream& stream) { return std::max(1, static_cast<int>(std::lround(1.0 / stream.period()))); }

// Whether a still run turns: its first and last thirds' means more than kPoseDriftRad of the radius
// apart. A slow motion (a short window and a high threshold take a second of a turn at 10 degrees
// per second for a pose) turns by degrees; a hand-held pose settles by less (the public logs' poses:
// at most 0.16 degrees on the Xsens, 0.55 on the noisier MPU-6050).
bool drifts(const LogStream& stream, int i, int j) {
  const int third = (j - i + 1) / 3;
  const double radius = stream.field_radius();
  if (third < 2 || !(radius > 0)) return false;
  int count = 0;
  const Vec3 none = Vec3::Zero();
  const Vec3 first = mean_of(stream, i, i + third - 1, none, count),
             last = mean_of(stream, j - third + 1, j, none, count);
  return (first - last).norm() > kPoseDriftRad * radius;
}

}  // namespace

StillPoseDetector::StillPoseDetector(StaticIntervalOptions options) : options_(options) {
  floor_from_still_ = options_.still_seconds > 0;
}

// The window in samples, once the stream's period is fixed: window_seconds of samples, at least
// 11, odd, at most the log so far (which only binds on a log shorter than one window).
bool StillPoseDetector::fix_window(const LogStream& stream) {
  if (window_ > 0) return true;
  const double period = stream.period_for(options_.window_seconds);
  if (!(period > 0)) return false;
  const int n = stream.log().size();
  if (!stream.ended() && static_cast<double>(n) < options_.window_seconds / period)
    return false;  // a window's span yet
  // In doubles first: a log whose time steps are tiny would overflow an int.
  const double window = std::clamp(options_.window_seconds / period, 11.0, static_cast<double>(std::max(n, 11)));
  window_ = std::max(11, static_cast<int>(std::lround(window)) | 1);
  return true;
}

void StillPoseDetector::extend_variances(const LogStream& stream) {
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

// The initial still period (--still), once the stream is past it: its usable samples and, when they
// fill a window, their variance norm as the floor. False while the period goes on.
bool StillPoseDetector::settle_still_period(const LogStream& stream) {
  const RawLog& log = stream.log();
  const int first = stream.first_usable();
  if (first < 0) return false;
  const double end = log.t[static_cast<std::size_t>(first)] + options_.still_seconds;
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  int count = 0, i = first;
  for (; i < stream.decided() && log.t[static_cast<std::size_t>(i)] <= end; ++i)
    if (stream.usable()[static_cast<std::size_t>(i)]) {
      const Vec3 s = log.samples[static_cast<std::size_t>(i)] - log.samples[static_cast<std::size_t>(first)];
      sum += s;
      sum2 += s.cwiseProduct(s);
      ++count;
    }
  if (i == stream.decided() && !stream.ended()) return false;
  still_settled_ = true;
  still_samples_ = count;
  if (count < window_) return true;  // detection() says why
  const Vec3 mean = sum / count;
  floor_ = (sum2 / count - mean.cwiseProduct(mean)).cwiseMax(0.0).norm();
  return true;
}

// The floor: the initial still period's variance (--still), once the stream is past it; else the
// quiet windows' median, recomputed as the windows grow by a sixty-fourth (the whole log at its end),
// and trusted once white windows make up the 5 % of the windows whose quantile it starts from (and at
// least a window's worth): before, the quietest windows could be a slow motion's.
bool StillPoseDetector::update_floor(const LogStream& stream) {
  if (floor_from_still_) {
    if (!still_settled_ && !settle_still_period(stream)) return false;  // the still period goes on
  } else if (!finite_.empty() && finite_.size() != floor_windows_) {
    const bool trusted = white_ >= kFloorWhiteWindows * window_ && 20.0 * white_ >= static_cast<double>(finite_.size());
    if (!stream.ended() &&
        (!trusted || finite_.size() < floor_windows_ + std::max<std::size_t>(1, floor_windows_ / 64)))
      return floor_ > 0;
    floor_ = quiet_floor(finite_);
    floor_windows_ = finite_.size();
  }
  threshold_ = options_.threshold_factor * floor_;
  return floor_ > 0;
}

void StillPoseDetector::advance(const LogStream& stream) {
  if (!fix_window(stream)) return;
  extend_variances(stream);
  if (!update_floor(stream)) return;
  judge(stream, static_cast<int>(variances_.size()));
  if (!stream.ended()) return;
  if (run_) close_run(stream);
  if (pending_) settle_pending(stream);
}

// The run-length rules, sample by sample: a still sample opens or grows the run; a moving one closes
// it; a merged run no later run can join any more (a break longer than a second) is settled.
void StillPoseDetector::judge(const LogStream& stream, int upto) {
  const int gap = longest_break(stream);
  for (int i = judged_; i < upto; ++i) {
    const double v = variances_[static_cast<std::size_t>(i)];
    if (std::isfinite(v) && v < threshold_) {
      if (run_)
        run_->second = i;
      else
        run_.emplace(i, i);
      continue;
    }
    if (run_) close_run(stream);
    if (pending_ && i - pending_->end - 1 >= gap) settle_pending(stream);
  }
  judged_ = upto;
}

// Still runs a short break apart whose means agree within the noise are one pose: a window whose
// noise happened to cross the threshold must not split it (a short window and a low threshold would
// otherwise count one pose as several, each an independent position to the fit). A break of at
// most a second; means within 6 standard errors of their difference, one sample's variance per axis
// taken from the floor (its norm over three equal variances is sqrt(3) sigma^2).
void StillPoseDetector::close_run(const LogStream& stream) {
  const auto [first, last] = *run_;
  run_.reset();
  const int gap = longest_break(stream);
  if (pending_ && first - pending_->end - 1 <= gap) {
    const Vec3 shift = stream.log().samples[static_cast<std::size_t>(stream.first_usable())];
    const double sigma2 = floor_ / std::sqrt(3.0);
    int na = 0, nb = 0;
    const Vec3 a = mean_of(stream, pending_last_begin_, pending_->end, shift, na),
               b = mean_of(stream, first, last, shift, nb);
    if ((a - b).norm() <= 6 * std::sqrt(3 * sigma2 * (1.0 / na + 1.0 / nb))) {
      pending_->breaks.emplace_back(pending_->end + 1, first - 1);
      pending_->end = last;
      pending_last_begin_ = first;
      return;
    }
  }
  if (pending_) settle_pending(stream);
  pending_.emplace();
  pending_->begin = first;
  pending_->end = last;
  pending_last_begin_ = first;
}

// A merged run becomes a pose if it is long enough and does not turn.
void StillPoseDetector::settle_pending(const LogStream& stream) {
  StaticInterval iv = std::move(*pending_);
  pending_.reset();
  const RawLog& log = stream.log();
  const int n = log.size();
  const double period = stream.period();
  const int min_samples =
      static_cast<int>(std::clamp(std::ceil(options_.min_seconds / period), 1.0, static_cast<double>(n) + 1));
  if (iv.samples() < min_samples) {
    ++short_runs_;
    return;
  }
  if (drifts(stream, iv.begin, iv.end)) {
    ++drifting_runs_;
    return;
  }
  iv.start = log.t[static_cast<std::size_t>(iv.begin)];
  iv.stop = log.t[static_cast<std::size_t>(iv.end)];
  longest_samples_ = std::max(longest_samples_, iv.samples());
  intervals_.push_back(std::move(iv));
}

IntervalDetection StillPoseDetector::detection(const LogStream& stream) const {
  const RawLog& log = stream.log();
  if (stream.ended()) {
    if (!(stream.period() > 0)) throw InputError(log.file, 0, "fewer than two finite rows: no sample period");
    if (stream.first_usable() < 0)
      throw InputError(log.file, 0,
                       floor_from_still_
                           ? words("the initial still period ({still} ") + seconds(options_.still_seconds) +
                                 " s) holds no usable sample (every row is non-finite or saturated)"
                           : "no usable sample (every row is non-finite or saturated)");
    if (finite_.empty())
      throw InputError(log.file, 0,
                       "the log holds no complete window of " + std::to_string(window_) +
                           words(" usable samples; shorten {window}"));
    if (floor_from_still_ && still_samples_ < window_)
      throw InputError(log.file, 0,
                       words("the initial still period ({still} ") + seconds(options_.still_seconds) + " s) holds " +
                           std::to_string(still_samples_) + " usable samples, fewer than one variance window (" +
                           std::to_string(window_) +
                           words("); lengthen {still}, shorten {window}, or drop {still} (the noise "
                                 "floor then comes from the log's quiet windows)"));
    if (!(floor_ > 0))
      throw InputError(
          log.file, 0,
          std::string(floor_from_still_ ? "the initial still period" : "the log") +
              " has no noise at all (a constant or clipped output): nothing to set the static threshold by");
  }
  IntervalDetection d;
  stream.describe(d);
  d.intervals = intervals_;
  d.sample_period = stream.period();
  d.window = window_;
  d.still_variance = floor_;
  d.floor_from_still = floor_from_still_;
  d.threshold = threshold_;
  d.short_runs = short_runs_;
  d.drifting_runs = drifting_runs_;
  d.longest_fraction = static_cast<double>(longest_samples_) / log.size();
  return d;
}

}  // namespace scalcal
