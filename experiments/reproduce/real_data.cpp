// The real log (issue 12): data/xsens_acc.txt, an Xsens accelerometer placed by hand, calibrated end
// to end as `scalcal calibrate --measurements data/xsens_acc.txt --magnitude 9.81744` does it: the
// static intervals found, |a| of each before and after, the parameters, the program the positions
// turned out to be and the positions worth adding. Figure: fig13 (the log with the intervals
// shaded; |a| - g per interval). Data: real_log.csv, real_intervals.csv.
#include <algorithm>
#include <cmath>

#include "commands/calibration/calibrate.hpp"
#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/program/catalogue.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

namespace {

// The report's table of the estimated parameters with their standard errors, and the program the
// log's positions turned out to be, with the positions worth adding: all as `calibrate` gives them.
void report_parameters_and_program(Report& rep, const commands::CalibrateResult& c) {
  const AnyUnitsCalibration& a = c.fit;
  std::vector<std::vector<std::string>> rows;
  const char* names[3] = {"x", "y", "z"};
  const char* pairs[3] = {"xy", "yz", "zx"};
  for (int k = 0; k < 3; ++k) {
    rows.push_back({std::string("offset ") + names[k] + " (counts)", decimal(a.correction.offset(k), 8),
                    decimal(a.bias_std(k), 3)});
  }
  for (int k = 0; k < 3; ++k)
    rows.push_back(
        {std::string("gain ") + names[k] + " (counts per m/s²)", decimal(a.gain(k), 7), decimal(a.gain_std(k), 3)});
  for (int k = 0; k < 3; ++k)
    rows.push_back({std::string("γ_") + pairs[k] + " (rad)", decimal(a.correction.nonorthogonality(k), 5),
                    decimal(a.nonorthogonality_std(k), 3)});
  rep.table({"parameter", "estimate", "standard error (the larger of noise- and residual-based)"}, rows);
  const ModelEvaluation& ev = c.program.evaluation;
  std::string suggestions;
  for (const auto& s : c.program.suggested)
    suggestions += (suggestions.empty() ? "" : "; ") + std::string("(") + decimal(s.position(0), 4) + ", " +
                   decimal(s.position(1), 4) + ", " + decimal(s.position(2), 4) + ") → D " + decimal(s.value, 5);
  std::string values, efficiencies;
  for (CriterionKind k : kCriteria) {
    const std::string name(criterion_name(k));
    values += ", " + name + " = " + decimal(ev.value(k), 6);
    efficiencies += (efficiencies.empty() ? "" : ", ") + name + " " + decimal(c.program.efficiency[k.index()], 6);
  }
  rep.paragraph("The program the positions turned out to be (model " + std::string(model_name(c.model)) + "): N = " +
                std::to_string(ev.positions) + values + "; efficiency against the sphere's limits " + efficiencies +
                ". The positions that would improve D most, each with the earlier ones added (gravity's direction "
                "in the meter's frame): " +
                suggestions +
                ". The comparison with an independent SciPy fit is in `experiments/docs/real_data.md` of "
                "scalcal's source tree (a path, not a link: this report may be written anywhere).");
}

// fig13's gnuplot script: the log (a) over its static intervals and |a| - g per interval (b); two panels
// on the full page width, each key in one row above its panel's right end (a key outside on the right
// took a fifth of the width); the axes are x, y, z in dark, medium, light over light grey static
// intervals, with the tics drawn in front of the shading.
std::string fig13_script(const RawLog& log, const IntervalDetection& d) {
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < log.size(); ++i)
    if (log.finite(i)) {
      lo = std::min(lo, log.samples[static_cast<std::size_t>(i)].minCoeff());
      hi = std::max(hi, log.samples[static_cast<std::size_t>(i)].maxCoeff());
    }
  const double pad = 0.04 * (hi - lo), mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo) + pad;
  using namespace plots::style;
  return "set multiplot\nset grid\nset tics front\nset lmargin at screen 0.1\nset rmargin at screen 0.98\n"
         "set key at graph 1, graph 1 right bottom horizontal Left reverse samplen 2 width -1\n"
         "set label 1 '(a)' at graph 0, graph 1.04 left front\n"
         "set tmargin at screen 0.94\nset bmargin at screen 0.6\nset xlabel 't (s)'\n"
         "set xrange [0:" +
         csv_num(std::ceil(log.t.back() / 10) * 10) +
         "]\n"
         "set ylabel 'ADC counts'\nset style fill solid 1.0 noborder\nset yrange [" +
         csv_num(mid - half) + ":" + csv_num(mid + half) +
         "]\n"
         "plot 'real_intervals.csv' skip 1 using (($2+$3)/2):(" +
         csv_num(mid) + "):(($3-$2)/2):(" + csv_num(half) +
         ") with boxxyerror lc rgb '#e3e3e3' title 'static', \\\n"
         "     'real_log.csv' skip 1 using 1:2 with lines lw 1 lc rgb '" +
         dark +
         "' title 'x', \\\n"
         "     'real_log.csv' skip 1 using 1:3 with lines lw 1 lc rgb '" +
         medium +
         "' title 'y', \\\n"
         "     'real_log.csv' skip 1 using 1:4 with lines lw 1 lc rgb '" +
         light +
         "' title 'z'\n"
         "set label 1 '(b)'\nset tmargin at screen 0.44\nset bmargin at screen 0.12\nset xlabel 'static interval'\n"
         "set ylabel '| |a| − g | (m/s" +
         plots::sup("2") + ")'\nset xrange [0:" + std::to_string(d.intervals.size() + 1) +
         "]\nset yrange [*:*]\nset logscale y\nset format y '10" + plots::sup("%T") +
         "'\n"
         "plot 'real_intervals.csv' skip 1 using 1:(abs($5)) with points pt 6 ps 0.9 lw 1.5 lc rgb '" +
         grey +
         "' title 'before (one gain)', \\\n"
         "     'real_intervals.csv' skip 1 using 1:(abs($6)) with points pt 7 ps 0.9 lc rgb '" +
         dark + "' title 'after calibration'\nunset multiplot\n";
}

}  // namespace

void real_data(Context& ctx) {
  constexpr double kG = 9.81744;  // the publishers' local gravity
  auto& rep = ctx.report;
  rep.heading(2, "fig13 (new): a real accelerometer log calibrated end to end");
  ctx.progress.detail("static intervals and calibration");
  // The command the report quotes, with the CLI's own defaults (its option table), so the numbers
  // below are exactly what it prints.
  const std::string file = data_dir() + "/xsens_acc.txt";
  commands::Values values(commands::calibrate_table());
  values.set("--measurements", file);
  values.set("--magnitude", "9.81744");
  const commands::CalibrateResult c = commands::calibrate(commands::calibrate_request(values));
  // The report presents this calibration as a result: if it stopped being one (no convergence, or
  // parameters the positions cannot identify), it says so first instead of showing numbers as good.
  if (!c.converged() || !c.not_identifiable.empty()) {
    std::string why = c.converged() ? "" : "the fit did not converge (" + c.fit.estimate.summary.message + ")";
    for (const auto& p : c.not_identifiable) why += (why.empty() ? "" : "; ") + p;
    rep.paragraph("> **Not a trustworthy calibration:** " + why + ". The numbers below are shown as diagnosis only.");
  }
  const RawLog log = read_raw_log(file);  // again, for the plot: `calibrate` keeps only the intervals
  const IntervalDetection& d = *c.detection;
  // Before: the datasheet way, zero at 32768 and one gain for all three axes (the best such gain).
  std::vector<double> raw_norms;
  for (const auto& p : c.positions) raw_norms.push_back((p.mean - Vec3::Constant(32768)).norm());
  std::vector<double> sorted = raw_norms;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double one_gain = sorted[sorted.size() / 2] / kG;

  CsvWriter intervals(ctx.file("real_intervals.csv"),
                      {"interval", "start", "end", "samples", "before_minus_g", "after_minus_g"});
  double ss_before = 0, ss_after = 0;
  for (std::size_t k = 0; k < c.positions.size(); ++k) {
    const auto& p = c.positions[k];
    const double before = raw_norms[k] / one_gain - kG, after = p.residual;
    ss_before += before * before;
    ss_after += after * after;
    intervals.row({std::to_string(k + 1), csv_num(p.start), csv_num(p.end), std::to_string(p.samples), csv_num(before),
                   csv_num(after)});
  }
  intervals.close();
  const double n = static_cast<double>(c.positions.size());
  const double rms_before = std::sqrt(ss_before / n) / kG, rms_after = std::sqrt(ss_after / n) / kG;
  // The log itself, every 5th row (its shape, not its noise, is what the figure shows).
  CsvWriter raw(ctx.file("real_log.csv"), {"t", "ix", "iy", "iz"});
  for (int i = 0; i < log.size(); i += 5)
    if (log.finite(i))
      raw.row({csv_num(log.t[static_cast<std::size_t>(i)]), csv_num(log.samples[static_cast<std::size_t>(i)](0)),
               csv_num(log.samples[static_cast<std::size_t>(i)](1)),
               csv_num(log.samples[static_cast<std::size_t>(i)](2))});
  raw.close();

  const std::string body = fig13_script(log, d);
  render_figure(ctx, "fig13", "the Xsens log with its static intervals, and |a| - g per interval before and after",
                body, plots::kPageWidthCm, 9.5);
  rep.figure("fig13",
             "fig13: (a) the raw log (ADC counts) with the static intervals scalcal found (shaded); (b) "
             "| |a| − g | of each interval's mean before calibration (zero at 32768, one gain for all three "
             "axes) and after");
  rep.paragraph("`scalcal calibrate --measurements data/xsens_acc.txt --magnitude 9.81744` on the log of IMU-TK (" +
                std::to_string(log.size()) + " rows, 100 Hz; BSD licence, data/README.md), whose numbers these are: " +
                std::to_string(d.intervals.size()) + " static intervals (window " + std::to_string(d.window) +
                " samples, threshold " + decimal(d.threshold, 4) +
                " counts² = 6 × the noise floor of the log's quiet windows), " + std::to_string(c.excluded.size()) +
                " outlier sample(s) excluded, model " + std::string(model_name(c.model)) + ", " +
                std::to_string(c.fit.estimate.iterations) +
                " iterations from the ellipsoid start. RMS of |a| − g over the intervals: " + decimal(rms_before, 3) +
                " of g before (one gain " + decimal(one_gain, 5) + " counts per m/s²), " + decimal(rms_after, 3) +
                " after. Data: [real_intervals.csv](real_intervals.csv), [real_log.csv](real_log.csv) (every 5th "
                "row).");
  report_parameters_and_program(rep, c);
}

}  // namespace scalcal::reproduce
