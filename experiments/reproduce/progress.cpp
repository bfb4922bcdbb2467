// A reproduce run's progress on stderr with the time left (progress.hpp).
#include "experiments/reproduce/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>

namespace scalcal::reproduce {

ProgressMode progress_mode(bool quiet, bool stderr_is_terminal) {
  if (quiet) return ProgressMode::off;
  return stderr_is_terminal ? ProgressMode::terminal : ProgressMode::lines;
}

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  return text;
}

Progress::Progress(ProgressMode mode, std::ostream* out) : mode_(mode), out_(out ? *out : std::cerr) {}

void Progress::plan(std::vector<std::string> names, std::vector<double> weights) {
  names_ = std::move(names);
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  starts_.clear();
  shares_.clear();
  double at = 0;
  for (double w : weights) {
    starts_.push_back(at);
    shares_.push_back(total > 0 ? w / total : 0);
    at += shares_.back();
  }
}

void Progress::begin_stage(std::size_t index) {
  stage_ = index;
  part_start_ = 0;
  part_share_ = 1;
  in_part_ = 0;
  what_.clear();
  if (mode_ == ProgressMode::lines && index < names_.size()) {
    out_ << "[reproduce] " << index + 1 << "/" << names_.size() << " " << names_[index] << ": "
         << static_cast<int>(100 * fraction()) << " % of the work done, " << remaining() << "\n"
         << std::flush;
  }
  show(true);
}

void Progress::part(double start, double share, const std::string& what) {
  part_start_ = std::clamp(start, 0.0, 1.0);
  part_share_ = std::clamp(share, 0.0, 1.0 - part_start_);
  in_part_ = 0;
  what_ = what;
  show(true);
}

void Progress::step(long long done, long long total) {
  if (total > 0) in_part_ = std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0);
  show(false);
}

void Progress::detail(const std::string& what) {
  what_ = what;
  show(true);
}

void Progress::done() {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (mode_ == ProgressMode::terminal) out_ << "\r\033[K" << std::flush;
  if (mode_ == ProgressMode::lines) out_ << "[reproduce] done in " << duration_text(s) << "\n" << std::flush;
}

double Progress::fraction() const {
  if (stage_ >= shares_.size()) return stage_ == 0 ? 0.0 : 1.0;
  return std::min(1.0, starts_[stage_] + shares_[stage_] * (part_start_ + part_share_ * in_part_));
}

std::string Progress::remaining() const {
  const double f = fraction();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // Before a thousandth of the work or a tenth of a second the ratio is mostly noise.
  if (f < 1e-3 || s < 0.1) return "estimating the time left";
  return "about " + duration_text(s * (1 - f) / f) + " left";
}

void Progress::show(bool force) {
  if (mode_ != ProgressMode::terminal) return;
  // A redraw at most every 0.2 s: the optimiser's workers report every start.
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - shown_ < std::chrono::milliseconds(200)) return;
  shown_ = now;
  const std::string stage = stage_ < names_.size() ? names_[stage_] : std::string();
  out_ << "\r\033[K[reproduce] " << stage << (what_.empty() ? "" : ": " + what_) << "  "
       << static_cast<int>(100 * fraction()) << " %, " << remaining() << std::flush;
}

}  // namespace scalcal::reproduce
