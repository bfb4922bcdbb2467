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

StillPoseDetector::StillPoseDetector(StaticIntervalOptions options, std::shared_ptr<MovingVariance> windows)
    : options_(options), windows_(std::move(windows)) {
  floor_from_still_ = options_.still_seconds > 0;
  if (!windows_) windows_ = std::make_shared<MovingVariance>(options_.window_seconds, !floor_from_still_);
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
  if (count < windows_->window()) return true;  // detection() says why
  const Vec3 mean = sum / count;
  floor_ = (sum2 / count - mean.cwiseProduct(mean)).cwiseMax(0.0).norm();
  return true;
}

// The floor: the initial still period's variance (--still), once the stream is past it; else the
// quiet windows' (MovingVariance::floor).
bool StillPoseDetector::update_floor(const LogStream& stream) {
  if (floor_from_still_) {
    if (!still_settled_ && !settle_still_period(stream)) return false;  // the still period goes on
  } else {
    floor_ = windows_->floor();
  }
  threshold_ = options_.threshold_factor * floor_;
  return floor_ > 0;
}

void StillPoseDetector::advance(const LogStream& stream) {
  windows_->advance(stream);  // shared: only the first detector's call of a chunk does the work
  if (windows_->window() == 0) return;
  if (!update_floor(stream)) return;
  judge(stream, static_cast<int>(windows_->variances().size()));
  if (!stream.ended()) return;
  if (run_) close_run(stream);
  if (pending_) settle_pending(stream);
}

// The run-length rules, sample by sample: a still sample opens or grows the run; a moving one closes
// it; a merged run no later run can join any more (a break longer than a second) is settled.
void StillPoseDetector::judge(const LogStream& stream, int upto) {
  const int gap = longest_break(stream);
  for (int i = judged_; i < upto; ++i) {
    const double v = windows_->variances()[static_cast<std::size_t>(i)];
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
    if (!windows_->any_complete_window())
      throw InputError(log.file, 0,
                       "the log holds no complete window of " + std::to_string(windows_->window()) +
                           words(" usable samples; shorten {window}"));
    if (floor_from_still_ && still_samples_ < windows_->window())
      throw InputError(log.file, 0,
                       words("the initial still period ({still} ") + seconds(options_.still_seconds) + " s) holds " +
                           std::to_string(still_samples_) + " usable samples, fewer than one variance window (" +
                           std::to_string(windows_->window()) +
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
  d.window = windows_->window();
  d.still_variance = floor_;
  d.floor_from_still = floor_from_still_;
  d.threshold = threshold_;
  d.short_runs = short_runs_;
  d.drifting_runs = drifting_runs_;
  d.longest_fraction = static_cast<double>(longest_samples_) / log.size();
  return d;
}

}  // namespace scalcal
