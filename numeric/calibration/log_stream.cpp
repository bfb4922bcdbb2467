// A raw log taken in chunks: what its samples are, whatever the detection's options (log_stream.hpp).
#include "numeric/calibration/log_stream.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

constexpr std::size_t kLinesKept = 5;

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

double median_of(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

LogStream::LogStream(std::string file)
    : finite_lo_(Vec3::Constant(INFINITY)),
      finite_hi_(Vec3::Constant(-INFINITY)),
      usable_lo_(Vec3::Constant(INFINITY)),
      usable_hi_(Vec3::Constant(-INFINITY)),
      ps_(1, Vec3::Zero()),
      ps2_(1, Vec3::Zero()),
      bad_(1, 0),
      steps2_(1, 0.0) {
  log_.file = std::move(file);
}

void LogStream::add(const RawLog& chunk, bool last) {
  if (ended_) throw InputError(log_.file, 0, "the log has ended: no chunk can follow its last");
  const int from = log_.size();
  log_.t.insert(log_.t.end(), chunk.t.begin(), chunk.t.end());
  log_.samples.insert(log_.samples.end(), chunk.samples.begin(), chunk.samples.end());
  log_.lines.insert(log_.lines.end(), chunk.lines.begin(), chunk.lines.end());
  take_rows(from, last);
}

// The first chunk is the log's storage itself (the batch's one chunk: the log is not copied).
void LogStream::add(RawLog&& chunk, bool last) {
  if (ended_ || log_.size() > 0) {
    add(static_cast<const RawLog&>(chunk), last);
    return;
  }
  std::string file = std::move(log_.file);
  log_ = std::move(chunk);
  log_.file = std::move(file);
  take_rows(0, last);
}

RawLog LogStream::release() && { return std::move(log_); }

// The rows from `from` on: their steps and extremes, then which samples are decided.
void LogStream::take_rows(int from, bool last) {
  // A chunk without line numbers (a caller's samples, not a file's) numbers its rows from 1 on.
  while (static_cast<int>(log_.lines.size()) < log_.size())
    log_.lines.push_back(static_cast<int>(log_.lines.size()) + 1);
  for (int index = from; index < log_.size(); ++index) {
    const auto k = static_cast<std::size_t>(index);
    if (!log_.finite(index)) continue;
    if (previous_finite_ >= 0) {
      const double step = log_.t[k] - log_.t[static_cast<std::size_t>(previous_finite_)];
      if (!(step > 0))
        throw InputError(log_.file, log_.lines[k], "time does not increase from the previous finite row's");
      steps_.push_back(step);
    }
    previous_finite_ = index;
    finite_lo_ = finite_lo_.cwiseMin(log_.samples[k]);
    finite_hi_ = finite_hi_.cwiseMax(log_.samples[k]);
  }
  ended_ = last;
  decide_usable(ended_ ? log_.size() : log_.size() - 2);
}

// Samples that sit at an output's extreme so far, at a rail, in a run of three or more
// consecutive rows: a clipped (saturated) output, whose value says nothing about the field.
bool LogStream::saturated(int k) const {
  const int n = log_.size();
  const auto at = [&](int j, int c, double e) {
    return j >= 0 && j < n && log_.finite(j) && log_.samples[static_cast<std::size_t>(j)](c) == e;
  };
  for (int c = 0; c < 3; ++c)
    for (double extreme : {finite_lo_(c), finite_hi_(c)}) {
      if (!is_rail(extreme) || !at(k, c, extreme)) continue;
      int run = 1;
      for (int j = k - 1; j >= k - 2 && at(j, c, extreme); --j) ++run;
      for (int j = k + 1; j <= k + 2 && at(j, c, extreme); ++j) ++run;
      if (run >= 3) return true;
    }
  return false;
}

void LogStream::decide_usable(int upto) {
  for (int k = decided(); k < upto; ++k) {
    const auto i = static_cast<std::size_t>(k);
    bool ok = log_.finite(k);
    if (!ok) {
      ++nonfinite_;
      if (nonfinite_lines_.size() < kLinesKept) nonfinite_lines_.push_back(log_.lines[i]);
    } else if (saturated(k)) {
      ok = false;
      ++saturated_;
      if (saturated_lines_.size() < kLinesKept) saturated_lines_.push_back(log_.lines[i]);
    }
    usable_.push_back(ok ? 1 : 0);
    if (ok && first_usable_ < 0) first_usable_ = k;
    const Vec3 s = ok ? Vec3(log_.samples[i] - log_.samples[static_cast<std::size_t>(first_usable_)]) : Vec3::Zero();
    ps_.push_back(ps_.back() + s);
    ps2_.push_back(ps2_.back() + s.cwiseProduct(s));
    bad_.push_back(bad_.back() + (ok ? 0 : 1));
    const bool pair = ok && k > 0 && usable_[i - 1];
    steps2_.push_back(steps2_.back() + (pair ? (log_.samples[i] - log_.samples[i - 1]).squaredNorm() : 0.0));
    if (!ok) continue;
    usable_lo_ = usable_lo_.cwiseMin(log_.samples[i]);
    usable_hi_ = usable_hi_.cwiseMax(log_.samples[i]);
    largest_ = std::max(largest_, log_.samples[i].cwiseAbs().maxCoeff());
  }
  // The variances sum squares of the samples, and the calibration's fit fourth powers: a log of
  // values so large that these overflow (data scaled by 1e160) would have no finite variance or no
  // fit and be reported as flat or unusable, so the overflow is named instead.
  const double squared = largest_ * largest_;
  if (squared * squared * log_.size() < 1e300) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "samples reach %.3g: the fit's fourth powers overflow double precision (beyond 1e308); "
                "rescale the log (e.g. to its physical units)",
                largest_);
  throw InputError(log_.file, 0, text);
}

double LogStream::period_for(double window_seconds) const {
  if (period_) return *period_;
  if (steps_.empty()) return 0;
  const double period = median_of(steps_);
  // A stream fixes its period once it has seen a window's span at that period (the whole log: the batch's).
  if (ended_ || static_cast<double>(log_.size()) * period >= window_seconds) period_ = period;
  return period_ ? *period_ : 0;
}

double LogStream::window_variance(int i, int h) const {
  const auto a = static_cast<std::size_t>(i - h), b = static_cast<std::size_t>(i + h + 1);
  if (i < h || bad_[b] - bad_[a] > 0) return NAN;
  return window_variance_norm(ps_[b] - ps_[a], ps2_[b] - ps2_[a], 2 * h + 1);
}

bool LogStream::window_white(int i, int h) const {
  const auto a = static_cast<std::size_t>(i - h), b = static_cast<std::size_t>(i + h + 1);
  const int w = 2 * h + 1;
  const double trace = window_axis_variances(ps_[b] - ps_[a], ps2_[b] - ps2_[a], w).sum();
  return (steps2_[b] - steps2_[a + 1]) / (w - 1) >= 0.5 * trace;
}

double LogStream::field_radius() const {
  std::vector<double> half;
  for (int c = 0; c < 3; ++c) half.push_back((usable_hi_(c) - usable_lo_(c)) / 2);
  std::sort(half.begin(), half.end());
  return half[1];
}

void LogStream::describe(IntervalDetection& d) const {
  d.nonfinite = nonfinite_;
  d.saturated = saturated_;
  d.nonfinite_lines = nonfinite_lines_;
  d.saturated_lines = saturated_lines_;
  d.usable = usable_;
}

}  // namespace scalcal
