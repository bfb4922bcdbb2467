// Tables 1-3 of the paper: its N = 18 programs for the A, E and S criteria beside scalcal's
// optimised programs for the same criterion, both evaluated on every criterion.
// Data: tables.csv, and scalcal's programs as table{1,2,3}_scalcal.csv (x, y, z, azimuth, elevation).
#include <fstream>
#include <stdexcept>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/program/program_csv.hpp"
#include "plots/csv_writer.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

namespace {
double value(const Evaluation& ev, CriterionKind c) { return ev.value(c); }
}  // namespace

void tables_1_2_3(Context& ctx) {
  auto& r = ctx.report;
  r.heading(2, "Tables 1-3: the paper's N = 18 programs beside scalcal's");
  r.paragraph(
      "The paper prints the angles (azimuth alpha1, elevation alpha2, 0.1° resolution) and no criterion "
      "values; scalcal evaluates them and optimises the same criterion. Data: [tables.csv](tables.csv).");
  CsvWriter csv(ctx.file("tables.csv"), {"table", "criterion", "program", "N", "D", "A", "E", "S", "theta_bias",
                                         "theta_scale", "theta_nonorth", "criterion_value", "limit"});
  const CriterionKind crit[] = {CriterionKind::A, CriterionKind::E, CriterionKind::S};
  for (int t = 0; t < 3; ++t) {
    const CriterionKind c = crit[t];
    const double lim = criterion_limit(c).value;
    const std::string cn(criterion_name(c));
    std::vector<std::vector<std::string>> rows;
    auto add = [&](const std::string& label, const Entry& e) {
      const auto& v = e.ev;
      rows.push_back({label, decimal(v.value(CriterionKind::D), 7), decimal(v.value(CriterionKind::A), 7),
                      decimal(v.value(CriterionKind::E), 7), decimal(v.value(CriterionKind::S), 7),
                      decimal(v.theta_bias, 5), decimal(v.theta_scale, 5), decimal(v.theta_nonorth, 5),
                      pct(value(v, c), lim)});
      csv.row({std::to_string(t + 1), cn, e.name, std::to_string(v.positions), csv_num(v.value(CriterionKind::D)),
               csv_num(v.value(CriterionKind::A)), csv_num(v.value(CriterionKind::E)),
               csv_num(v.value(CriterionKind::S)), csv_num(v.theta_bias), csv_num(v.theta_scale),
               csv_num(v.theta_nonorth), csv_num(value(v, c)), csv_num(lim)});
    };
    const Entry& paper = ctx.paper[static_cast<std::size_t>(t)];
    add("paper Table " + std::to_string(t + 1), paper);
    const Entry* ours = ctx.optimum(c, 18);
    if (ours) {
      add("scalcal " + cn + "-optimal", *ours);
      const auto path = ctx.file("table" + std::to_string(t + 1) + "_scalcal.csv");
      std::ofstream out(path);
      write_program_csv(out, ours->program);
      out.close();
      if (!out) throw std::runtime_error("cannot write " + path.string());
    }
    r.heading(3, "Table " + std::to_string(t + 1) + ": " + cn + "-criterion, N = 18");
    r.table({"program", "D", "A", "E", "S", "θ_bias", "θ_scale", "θ_nonorth", cn + " above its limit"}, rows);
    r.paragraph("Limit of " + cn + " for N → ∞: " + exact_and_decimal(criterion_limit(c).exact, lim, 8) + "." +
                (ours ? " scalcal's program: [table" + std::to_string(t + 1) + "_scalcal.csv](table" +
                            std::to_string(t + 1) + "_scalcal.csv)."
                      : ""));
    if (ours)
      r.claim("Table " + std::to_string(t + 1) + " program, " + cn + " value (evaluated from the printed angles)",
              decimal(value(paper.ev, c), 7), decimal(value(ours->ev, c), 7) + " (scalcal optimum)",
              pct(value(ours->ev, c), value(paper.ev, c)));
    else {
      r.missing("scalcal's " + cn + "-optimal N = 18 program: the optimiser's result was rejected");
      r.claim("Table " + std::to_string(t + 1) + " program, " + cn + " value (evaluated from the printed angles)",
              decimal(value(paper.ev, c), 7), "MISSING (no optimiser)", "n/a");
    }
  }
}

}  // namespace scalcal::reproduce
