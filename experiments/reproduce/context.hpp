// The shared state of one `scalcal reproduce` run: the programs of every class are computed once
// (programs.hpp), then each figure or table (figures.hpp) writes its CSV, its gnuplot script, its
// PDF, PNG and SVG and its section of REPORT.md from them; progress.hpp reports how far the run is.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "experiments/reproduce/progress.hpp"
#include "experiments/reproduce/report.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::reproduce {

struct Options {
  std::filesystem::path out = "results";
  bool quick = false;      // small sweeps, for the tests: within a minute on two cores
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

struct Context {
  Context(Options o, ProgressMode mode) : options(std::move(o)), progress(mode) {}
  Options options;
  Progress progress;
  Report report;

  std::vector<std::string> optimiser_failures;  // optimised programs rejected by scalcal's own evaluation

  std::vector<Entry> uniform, rotation, jigs, paper, analytic9;  // analytic classes and the paper's tables
  std::vector<Entry> printable;      // the registry's printable jigs (group "jig"), default mounting, full rank
  std::map<int, Entry> random_best;  // best of random_count programs per N (D)
  long long random_count = 0;
  std::map<std::pair<CriterionKind, int>, Entry> optimised;  // (criterion, N)
  std::vector<std::pair<std::string, double>> timings;       // stage, seconds

  const Entry* optimum(CriterionKind c, int n) const;
  std::vector<int> optimised_sizes(CriterionKind c) const;
  std::filesystem::path file(const std::string& name) const { return options.out / name; }
  int threads() const;
};

}  // namespace scalcal::reproduce
