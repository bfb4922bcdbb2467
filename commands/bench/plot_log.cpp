// The log's figure of `scalcal plot --log FILE --calibration CAL.json` (plot.hpp): the reproduction's
// fig13 drawing for any log and its calibration.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "commands/bench/plot.hpp"
#include "commands/core/json.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

// Paul Tol's colours (plots/figure.hpp, style): x, y, z dark, medium, light; reference marks grey.
constexpr const char* kDark = "#004488";
constexpr const char* kMedium = "#BB5566";
constexpr const char* kLight = "#DDAA33";
constexpr const char* kGrey = "#777777";
constexpr int kMaxLogRows = 20000;  // drawn from the log (every k-th row beyond): its shape, not its noise

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.9g", v);
  return s;
}

struct Interval {
  double start, end, residual;
  Vec3 mean;
  int samples = -1;      // -1: the file does not say
  double celsius = NAN;  // a thermal calibration's pose: its mean temperature
};

// A thermal calibration's poses (calibrate --model BASE+Tk --out): t_c, start_s, stop_s, mean, samples and
// residual (|corrected| / |I| - 1, drawn as |I| times it).
std::vector<Interval> poses_of(const Json& j, const std::string& file, double magnitude) {
  std::vector<Interval> out;
  for (const auto& p : j["poses"]) {
    if (!p.is_object() || !p["t_c"].is_number() || !p["start_s"].is_number() || !p.contains("stop_s") ||
        !p["stop_s"].is_number() || !p["residual"].is_number() || !p["mean"].is_array() || p["mean"].size() != 3 ||
        !p["samples"].is_number_integer())
      throw InputError(file, 0,
                       words("its poses need t_c, start_s, stop_s, mean, samples and residual (calibrate {out})"));
    out.push_back({p["start_s"].get<double>(), p["stop_s"].get<double>(), magnitude * p["residual"].get<double>(),
                   Vec3(p["mean"][0].get<double>(), p["mean"][1].get<double>(), p["mean"][2].get<double>()),
                   p["samples"].get<int>(), p["t_c"].get<double>()});
  }
  return out;
}

// The calibration's intervals (start, end in seconds, raw mean, residual) and |I|.
std::vector<Interval> intervals_of(const std::string& file, double& magnitude) {
  Json j = parse_json_file_text(read_text_file(file), file);
  if (j.is_object() && j.contains("poses") && j["poses"].is_array()) {
    magnitude = j.contains("magnitude") && j["magnitude"].is_number() ? j["magnitude"].get<double>() : 1.0;
    std::vector<Interval> out = poses_of(j, file, magnitude);
    if (out.empty()) throw InputError(file, 0, "no poses");
    return out;
  }
  if (!j.is_object() || !j.contains("intervals") || !j["intervals"].is_array())
    throw InputError(file, 0, words("not a calibration of a log (calibrate {out}): it has no 'intervals'"));
  magnitude = j.contains("magnitude") && j["magnitude"].is_number() ? j["magnitude"].get<double>() : 1.0;
  std::vector<Interval> out;
  for (const auto& i : j["intervals"]) {
    if (!i.is_object() || !i["start"].is_number() || !i["end"].is_number() || !i["residual"].is_number() ||
        !i["mean"].is_array() || i["mean"].size() != 3)
      throw InputError(file, 0, "its intervals need start and end times (a raw log's calibration), mean and residual");
    out.push_back({i["start"].get<double>(), i["end"].get<double>(), i["residual"].get<double>(),
                   Vec3(i["mean"][0].get<double>(), i["mean"][1].get<double>(), i["mean"][2].get<double>()),
                   i.contains("samples") && i["samples"].is_number_integer() ? i["samples"].get<int>() : -1});
  }
  if (out.empty()) throw InputError(file, 0, "no intervals");
  return out;
}

// The calibration must be this log's: each of its intervals holds, in the log, at least as many
// finite rows as it says, and their sum is its mean times their number but for the rows calibrate left
// out as outliers (each at most the farthest row's distance from the mean), to rounding. Another log's
// would be drawn over the wrong samples (a rehearsal of the same program has the same times, other means).
void refuse_other_log(const PlotRequest& q, const RawLog& log, const std::vector<Interval>& intervals) {
  std::vector<double> t;  // the finite rows' times, increasing, and their rows
  std::vector<int> row;
  for (int i = 0; i < log.size(); ++i)
    if (log.finite(i)) {
      t.push_back(log.t[static_cast<std::size_t>(i)]);
      row.push_back(i);
    }
  const auto fail = [&](std::size_t k, int n, const std::string& why) {
    const Interval& iv = intervals[k];
    return InputError(q.calibration, 0,
                      "interval " + std::to_string(k + 1) + " (" + num(iv.start) + " to " + num(iv.end) +
                          " s) is not in " + display_name(q.log) + " (" + std::to_string(n) + " rows" + why +
                          "): another log's calibration");
  };
  double previous_end = -INFINITY;
  for (std::size_t k = 0; k < intervals.size(); ++k) {
    const Interval& iv = intervals[k];
    // calibrate's intervals follow one another: overlapping ones are no log's (and would cost rows x intervals).
    if (!(iv.start > previous_end && iv.end >= iv.start)) throw fail(k, 0, ", out of order");
    previous_end = iv.end;
    const auto lo = std::lower_bound(t.begin(), t.end(), iv.start), hi = std::upper_bound(t.begin(), t.end(), iv.end);
    Vec3 sum = Vec3::Zero();
    double farthest = 0;
    for (auto it = lo; it != hi; ++it) {
      const Vec3& s = log.samples[static_cast<std::size_t>(row[static_cast<std::size_t>(it - t.begin())])];
      sum += s;
      farthest = std::max(farthest, (s - iv.mean).norm());
    }
    const int n = static_cast<int>(hi - lo), left_out = iv.samples < 0 ? 0 : n - iv.samples;
    const double rounding = 1e-9 * n * iv.mean.norm();
    if (n == 0 || left_out < 0 || 2 * left_out > n || !((sum - n * iv.mean).norm() <= left_out * farthest + rounding))
      throw fail(k, n, n > 0 ? ", another mean" : "");
  }
}

// Panel (b) of a log: |mean| - |I| per interval, before (one gain) and after calibration, on a log scale.
std::string residual_per_interval(std::size_t intervals) {
  return "set xlabel 'static interval'\nset ylabel '| |mean| − |I| |'\nset xrange [0:" + std::to_string(intervals + 1) +
         "]\nset yrange [*:*]\nset logscale y\nset format y '10^{/*1.1 %T}'\n"
         "plot intervals_file skip 1 using 1:(abs($4)) with points pt 6 ps 0.9 lw 1.5 lc rgb '" +
         std::string(kGrey) +
         "' title 'before (one gain)', \\\n"
         "     intervals_file skip 1 using 1:(abs($5)) with points pt 7 ps 0.9 lc rgb '" +
         kDark + "' title 'after calibration'\nunset multiplot\n";
}

// Panel (b) of a thermal log: each pose's residual after the thermal calibration against its temperature
// (signed, linear: a trend left in it is drift the model's degree missed).
std::string residual_against_temperature() {
  return "set xlabel 'temperature (°C)'\nset ylabel '|corrected| − |I|'\nset xrange [*:*]\nset yrange [*:*]\n"
         "set format y '%.0e'\n"
         "plot intervals_file skip 1 using 6:5 with points pt 7 ps 0.9 lc rgb '" +
         std::string(kDark) + "' title 'after calibration', 0 with lines lc rgb '" + kGrey +
         "' notitle\nunset multiplot\n";
}

}  // namespace

void plot_log(const PlotRequest& q, PlotResult& r) {
  double magnitude = 1;
  const std::vector<Interval> intervals = intervals_of(q.calibration, magnitude);
  const RawLog log = read_raw_log(q.log);
  refuse_other_log(q, log, intervals);
  // Before calibration: one gain for all axes and no offsets, the median |mean| over |I|.
  std::vector<double> norms;
  for (const auto& i : intervals) norms.push_back(i.mean.norm());
  std::vector<double> sorted = norms;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double gain = sorted[sorted.size() / 2] / magnitude;
  const bool thermal = !std::isnan(intervals.front().celsius);
  std::string iv = std::string("interval,start,end,before,after") + (thermal ? ",t_c" : "") + "\n";
  for (std::size_t k = 0; k < intervals.size(); ++k)
    iv += std::to_string(k + 1) + "," + num(intervals[k].start) + "," + num(intervals[k].end) + "," +
          num(norms[k] / gain - magnitude) + "," + num(intervals[k].residual) +
          (thermal ? "," + num(intervals[k].celsius) : "") + "\n";
  const int step = std::max(1, log.size() / kMaxLogRows);
  std::string rows = "t,ix,iy,iz\n";
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < log.size(); i += step) {
    if (!log.finite(i)) continue;
    const Vec3& s = log.samples[static_cast<std::size_t>(i)];
    rows += num(log.t[static_cast<std::size_t>(i)]) + "," + num(s(0)) + "," + num(s(1)) + "," + num(s(2)) + "\n";
    lo = std::min(lo, s.minCoeff());
    hi = std::max(hi, s.maxCoeff());
  }
  r.data.push_back({"log_file", r.stem + "_log.csv", rows});
  r.data.push_back({"intervals_file", r.stem + "_intervals.csv", iv});
  r.view = "log";
  r.comment = "the log " + display_name(q.log) + " with the static intervals of " + display_name(q.calibration) +
              ", and |mean| - |I| per interval before and after calibration";
  r.width_cm = 17.5;
  r.height_cm = 9.5;
  const double pad = 0.04 * (hi - lo), mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo) + pad;
  r.body =
      "set multiplot\nset grid\nset lmargin at screen 0.1\nset rmargin at screen 0.78\n"
      "set key outside right top Left reverse samplen 2 width -1\nset label 1 '(a)' at graph 0, graph 1.04 left front\n"
      "set tmargin at screen 0.94\nset bmargin at screen 0.6\nset xlabel 't (s)'\nset ylabel 'raw'\n"
      "set style fill solid 1.0 noborder\nset yrange [" +
      num(mid - half) + ":" + num(mid + half) +
      "]\n"
      "plot intervals_file skip 1 using (($2+$3)/2):(" +
      num(mid) + "):(($3-$2)/2):(" + num(half) +
      ") with boxxyerror lc rgb '#e3e3e3' title 'static', \\\n"
      "     log_file skip 1 using 1:2 with lines lw 1 lc rgb '" +
      kDark +
      "' title 'x', \\\n"
      "     log_file skip 1 using 1:3 with lines lw 1 lc rgb '" +
      kMedium +
      "' title 'y', \\\n"
      "     log_file skip 1 using 1:4 with lines lw 1 lc rgb '" +
      kLight +
      "' title 'z'\n"
      "set label 1 '(b)'\nset tmargin at screen 0.44\nset bmargin at screen 0.12\n" +
      (thermal ? residual_against_temperature() : residual_per_interval(intervals.size()));
}

}  // namespace scalcal::commands
