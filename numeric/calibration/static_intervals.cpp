// Static positions in a raw log, found from the log's own noise floor (static_intervals.hpp).
#include "numeric/calibration/static_intervals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

constexpr std::size_t kLinesKept = 5;

std::string seconds(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// An ADC's rail: zero, or an integer next to a power of two from 2^7 to 2^32 (full scale of an
// 8- to 32-bit converter, signed or unsigned). Only at a rail is a plateau clipping: a quiet output
// may well repeat its extreme value.
bool is_rail(double v) {
  if (v != std::floor(v)) return false;
  const double a = std::abs(v);
  if (a == 0) return true;
  for (int k = 7; k <= 32; ++k) {
    const double p = std::ldexp(1.0, k);
    if (a == p || a == p - 1) return true;
  }
  return false;
}

// Samples that sit at an output's overall extreme, at a rail, for three or more consecutive rows:
// a clipped (saturated) output, whose value says nothing about the field.
std::vector<char> saturated_samples(const RawLog& log) {
  const int n = log.size();
  std::vector<char> out(static_cast<std::size_t>(n), 0);
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; ++i)
      if (log.finite(i)) {
        lo = std::min(lo, log.samples[static_cast<std::size_t>(i)](c));
        hi = std::max(hi, log.samples[static_cast<std::size_t>(i)](c));
      }
    for (double extreme : {lo, hi}) {
      if (!is_rail(extreme)) continue;
      for (int i = 0; i < n;) {
        int j = i;
        while (j < n && log.finite(j) && log.samples[static_cast<std::size_t>(j)](c) == extreme) ++j;
        if (j - i >= 3)
          for (int k = i; k < j; ++k) out[static_cast<std::size_t>(k)] = 1;
        i = std::max(j, i + 1);
      }
    }
  }
  return out;
}

// The noise floor from the log itself: the median of the quiet windows, those below 3 times the 5 %
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

// The variances sum squares of the samples, and the calibration's fit fourth powers: a log of values
// so large that these overflow (data scaled by 1e160) would have no finite variance or no fit and be
// reported as flat or unusable, so the overflow is named instead.
void check_powers_fit(const RawLog& log, const std::vector<char>& usable) {
  double largest = 0;
  for (int i = 0; i < log.size(); ++i)
    if (usable[static_cast<std::size_t>(i)])
      largest = std::max(largest, log.samples[static_cast<std::size_t>(i)].cwiseAbs().maxCoeff());
  const double squared = largest * largest;
  if (squared * squared * log.size() < 1e300) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "samples reach %.3g: the fit's fourth powers overflow double precision (beyond 1e308); "
                "rescale the log (e.g. to its physical units)",
                largest);
  throw InputError(log.file, 0, text);
}

}  // namespace

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
    const Vec3 m = (ps[b] - ps[a]) / w;
    const Vec3 var = (ps2[b] - ps2[a]) / w - m.cwiseProduct(m);
    // The norm squares the variances again: beyond 1e150 it is taken scaled (it would overflow),
    // below unchanged (the same bits as always).
    const Vec3 v = var.cwiseMax(0.0);
    const double largest = v.maxCoeff();
    out[static_cast<std::size_t>(i)] = largest > 1e150 ? largest * (v / largest).norm() : v.norm();
  }
  return out;
}

namespace {

// The noise floor of the first still_seconds (--still): IMU-TK's way, for logs known to start still.
double still_floor(const RawLog& log, const std::vector<char>& usable, int first, const StaticIntervalOptions& o,
                   int window, const Vec3& shift) {
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  int count = 0;
  const double end = log.t[static_cast<std::size_t>(first)] + o.still_seconds;
  for (int i = first; i < log.size() && log.t[static_cast<std::size_t>(i)] <= end; ++i)
    if (usable[static_cast<std::size_t>(i)]) {
      const Vec3 s = log.samples[static_cast<std::size_t>(i)] - shift;
      sum += s;
      sum2 += s.cwiseProduct(s);
      ++count;
    }
  if (count < window)
    throw InputError(log.file, 0,
                     "the initial still period (--still " + seconds(o.still_seconds) + " s) holds " +
                         std::to_string(count) + " usable samples, fewer than one variance window (" +
                         std::to_string(window) +
                         "); lengthen --still, shorten --window, or drop --still (the noise "
                         "floor then comes from the log's quiet windows)");
  const Vec3 mean = sum / count;
  return (sum2 / count - mean.cwiseProduct(mean)).cwiseMax(0.0).norm();
}

// Marks the unusable samples (non-finite, saturated), counts them, and sets the sample period and
// the window in samples.
std::vector<char> usable_samples(const RawLog& log, const StaticIntervalOptions& options, IntervalDetection& d) {
  const int n = log.size();
  std::vector<char> usable(static_cast<std::size_t>(n), 1);
  const std::vector<char> clipped = saturated_samples(log);
  std::vector<double> steps;
  int previous = -1;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!log.finite(i)) {
      usable[k] = 0;
      ++d.nonfinite;
      if (d.nonfinite_lines.size() < kLinesKept) d.nonfinite_lines.push_back(log.lines[k]);
      continue;
    }
    if (clipped[k]) {
      usable[k] = 0;
      ++d.saturated;
      if (d.saturated_lines.size() < kLinesKept) d.saturated_lines.push_back(log.lines[k]);
    }
    if (previous >= 0) steps.push_back(log.t[k] - log.t[static_cast<std::size_t>(previous)]);
    previous = i;
  }
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  d.sample_period = steps[steps.size() / 2];
  // In doubles first: a log whose time steps are tiny would overflow an int.
  const double window =
      std::clamp(options.window_seconds / d.sample_period, 11.0, static_cast<double>(std::max(n, 11)));
  d.window = std::max(11, static_cast<int>(std::lround(window)) | 1);
  return usable;
}

// Still runs a short break apart whose means agree within the noise are one pose: a window whose
// noise happened to cross the threshold must not split it (a short window and a low threshold would
// otherwise count one pose as several, each an independent position to the fit). A break of at
// most a second; means within 6 standard errors of their difference, one sample's variance per axis
// taken from the floor (its norm over three equal variances is sqrt(3) sigma^2).
std::vector<StaticInterval> merged_runs(const RawLog& log, const std::vector<char>& usable, const Vec3& shift,
                                        const std::vector<std::pair<int, int>>& runs, double floor, double period) {
  const auto mean_of = [&](int i, int j, int& count) {
    Vec3 s = Vec3::Zero();
    count = 0;
    for (int k = i; k <= j; ++k)
      if (usable[static_cast<std::size_t>(k)]) s += log.samples[static_cast<std::size_t>(k)] - shift, ++count;
    return Vec3(s / std::max(count, 1));
  };
  const double sigma2 = floor / std::sqrt(3.0);
  const int longest_break = std::max(1, static_cast<int>(std::lround(1.0 / period)));
  std::vector<StaticInterval> out;
  int last_begin = 0;  // the last run merged into out.back(), whose mean the next run is judged against
  for (const auto& run : runs) {
    if (!out.empty() && run.first - out.back().end - 1 <= longest_break) {
      int na = 0, nb = 0;
      const Vec3 a = mean_of(last_begin, out.back().end, na), b = mean_of(run.first, run.second, nb);
      if ((a - b).norm() <= 6 * std::sqrt(3 * sigma2 * (1.0 / na + 1.0 / nb))) {
        out.back().breaks.emplace_back(out.back().end + 1, run.first - 1);
        out.back().end = run.second;
        last_begin = run.first;
        continue;
      }
    }
    StaticInterval iv;
    iv.begin = run.first;
    iv.end = run.second;
    out.push_back(iv);
    last_begin = run.first;
  }
  return out;
}

// Half the spread of the outputs, the median over the three: the field's radius in raw units where
// the log turns the meter round (less where it covers less, which only makes drifts() stricter).
double field_radius(const RawLog& log, const std::vector<char>& usable) {
  std::vector<double> half;
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < log.size(); ++i)
      if (usable[static_cast<std::size_t>(i)]) {
        lo = std::min(lo, log.samples[static_cast<std::size_t>(i)](c));
        hi = std::max(hi, log.samples[static_cast<std::size_t>(i)](c));
      }
    half.push_back((hi - lo) / 2);
  }
  std::sort(half.begin(), half.end());
  return half[1];
}

// Whether a still run turns: its first and last thirds' means more than kPoseDriftRad of the radius
// apart. A slow motion (a short window and a high threshold take a second of a turn at 10 degrees
// per second for a pose) turns by degrees; a hand-held pose settles by less (the public logs' poses:
// at most 0.16 degrees on the Xsens, 0.55 on the noisier MPU-6050).
bool drifts(const RawLog& log, const std::vector<char>& usable, int i, int j, double radius) {
  const int third = (j - i + 1) / 3;
  if (third < 2 || !(radius > 0)) return false;
  const auto mean = [&](int a, int b) {
    Vec3 s = Vec3::Zero();
    int n = 0;
    for (int k = a; k <= b; ++k)
      if (usable[static_cast<std::size_t>(k)]) s += log.samples[static_cast<std::size_t>(k)], ++n;
    return Vec3(s / std::max(n, 1));
  };
  return (mean(i, i + third - 1) - mean(j - third + 1, j)).norm() > kPoseDriftRad * radius;
}

}  // namespace

IntervalDetection detect_static_intervals(const RawLog& log, const StaticIntervalOptions& options) {
  IntervalDetection d;
  const int n = log.size();
  d.usable = usable_samples(log, options, d);
  const std::vector<char>& usable = d.usable;
  int first = 0;
  while (first < n && !usable[static_cast<std::size_t>(first)]) ++first;
  if (first == n && options.still_seconds > 0)
    throw InputError(log.file, 0,
                     "the initial still period (--still " + seconds(options.still_seconds) +
                         " s) holds no usable sample (every row is non-finite or saturated)");
  if (first == n) throw InputError(log.file, 0, "no usable sample (every row is non-finite or saturated)");
  const Vec3 shift = log.samples[static_cast<std::size_t>(first)];
  check_powers_fit(log, usable);
  const std::vector<double> variance = window_variances(log, usable, d.window, shift);
  std::vector<double> finite;
  for (double v : variance)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty())
    throw InputError(
        log.file, 0,
        "the log holds no complete window of " + std::to_string(d.window) + " usable samples; shorten --window");
  d.floor_from_still = options.still_seconds > 0;
  d.still_variance =
      d.floor_from_still ? still_floor(log, usable, first, options, d.window, shift) : quiet_floor(finite);
  if (!(d.still_variance > 0))
    throw InputError(log.file, 0,
                     std::string(d.floor_from_still ? "the initial still period" : "the log") +
                         " has no noise at all (a constant or clipped output): nothing to set the static threshold by");
  d.threshold = options.threshold_factor * d.still_variance;
  const auto is_static = [&](int i) {
    const double v = variance[static_cast<std::size_t>(i)];
    return std::isfinite(v) && v < d.threshold;
  };
  const int min_samples =
      static_cast<int>(std::clamp(std::ceil(options.min_seconds / d.sample_period), 1.0, static_cast<double>(n) + 1));
  std::vector<std::pair<int, int>> runs;
  for (int i = 0; i < n;) {
    if (!is_static(i)) {
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < n && is_static(j + 1)) ++j;
    runs.emplace_back(i, j);
    i = j + 1;
  }
  const double radius = field_radius(log, usable);
  for (StaticInterval iv : merged_runs(log, usable, shift, runs, d.still_variance, d.sample_period)) {
    if (iv.samples() >= min_samples && drifts(log, usable, iv.begin, iv.end, radius)) {
      ++d.drifting_runs;
      continue;
    }
    if (iv.samples() >= min_samples) {
      iv.start = log.t[static_cast<std::size_t>(iv.begin)];
      iv.stop = log.t[static_cast<std::size_t>(iv.end)];
      d.longest_fraction = std::max(d.longest_fraction, static_cast<double>(iv.samples()) / n);
      d.intervals.push_back(std::move(iv));
    } else {
      ++d.short_runs;
    }
  }
  return d;
}

}  // namespace scalcal
