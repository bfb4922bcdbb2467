// `scalcal reproduce`: the shared state of one run. The programs of every class are computed once
// (reproduce_programs.cpp) and then each figure or table (reproduce_fig*.cpp, reproduce_tables.cpp)
// writes its CSV, its gnuplot script, its PNG + SVG and its section of REPORT.md from them.
#pragma once
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "experiments/reproduce_report.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::reproduce {

struct Options {
  std::filesystem::path out = "results";
  bool quick = false;     // small sweeps, for the tests: within a minute on two cores
  std::uint64_t seed = 1;  // every random choice derives from this seed
  int threads = 0;         // 0: all cores
};

// A program with its evaluation and where it comes from.
struct Entry {
  std::string family;  // uniform, rotation, jig, optimised, random, paper, analytic
  std::string name;    // e.g. octahedral-1-1-0, rotation-6, optimised-D-18
  std::string source;  // the paper's reference or figure
  Program program;
  Evaluation ev;
  // Optimiser runs only:
  int starts = 0, hits = 0;
  double seconds = 0;
};

Entry make_entry(std::string family, std::string name, std::string source, Program program);

// Progress on stderr, only when stderr is a terminal.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled) {}
  void stage(const std::string& what);
  void step(long long done, long long total);
  void done();

 private:
  bool enabled_;
  std::string stage_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct Context {
  Context(Options o, bool show_progress) : options(std::move(o)), progress(show_progress) {}
  Options options;
  Progress progress;
  Report report;

  // Whether numeric/synthesis.cpp (the optimiser, issue 3) was in the tree at build time.
  bool optimiser = false;
  std::string optimiser_note;  // why optimised curves are missing, when they are
  std::vector<std::string> optimiser_failures;  // optimised programs rejected by scalcal's own evaluation

  std::vector<Entry> uniform, rotation, jigs, paper, analytic9;  // analytic classes and the paper's tables
  std::map<int, Entry> random_best;                              // best of random_count programs per N (D)
  long long random_count = 0;
  std::map<std::pair<CriterionKind, int>, Entry> optimised;       // (criterion, N)
  std::vector<std::pair<std::string, double>> timings;           // stage, seconds

  const Entry* optimum(CriterionKind c, int n) const;
  std::vector<int> optimised_sizes(CriterionKind c) const;
  std::filesystem::path file(const std::string& name) const { return options.out / name; }
  int threads() const;
};

// Stages, in the order `reproduce` runs them.
void compute_analytic(Context& ctx);
void compute_random(Context& ctx);
void compute_optimised(Context& ctx);
void figures_4_5_6(Context& ctx);
void figure_7(Context& ctx);
void figure_8(Context& ctx);
void figure_9(Context& ctx);
void figure_limits(Context& ctx);  // fig10: optimum of each criterion against N, with its limit
void figure_sphere(Context& ctx);  // fig11: the optimal N = 12 and 18 programs on the sphere
void tables_1_2_3(Context& ctx);
void summary(Context& ctx);        // the paper's stated numbers beside scalcal's, at the top

// Number formatting shared by the report and the CSVs.
std::string fmt(double x, int significant = 6);
std::string pct(double ours, double theirs);  // signed relative difference in percent

}  // namespace scalcal::reproduce

namespace scalcal::reproduce {

// The CSV columns describing one program (family, name, source, N, det K, D, A, E, S, thetas).
std::vector<std::string> entry_header();
std::vector<std::string> entry_cells(const Entry& e);

// The gnuplot `plot` command drawing column `column` of fig4_programs.csv for each program class of
// Fig. 4, and the random programs' dashed line (their D column when column is 6, else det K).
std::string class_plot(int column, const Context& ctx, bool with_limit);

// Paths are relative to the output folder; the figure scripts run there.
void render_figure(Context& ctx, const std::string& name, const std::string& comment, const std::string& body,
                   int width = 1100, int height = 750);

}  // namespace scalcal::reproduce
