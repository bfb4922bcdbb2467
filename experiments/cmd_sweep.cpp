// `scalcal sweep --positions 9..40 --criteria D,A,E,S [--starts K] [--seed S] [--out FILE]`: the
// best program for every N and criterion, with its ratio to the N -> infinity limit.
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "experiments/command.hpp"
#include "experiments/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::cli {
namespace {

std::pair<int, int> range_option(const std::string& s) {
  const auto dots = s.find("..");
  try {
    if (dots == std::string::npos) return {std::stoi(s), std::stoi(s)};
    return {std::stoi(s.substr(0, dots)), std::stoi(s.substr(dots + 2))};
  } catch (const std::exception&) {
    throw UsageError("--positions takes N or A..B, got '" + s + "'");
  }
}

int run(Args& args) {
  const auto [lo, hi] = range_option(args.text("positions", "9..40"));
  if (lo < 9 || hi < lo || hi > 1000) throw UsageError("--positions must be a range within 9..1000");
  std::vector<CriterionKind> criteria;
  std::stringstream list(args.text("criteria", "D,A,E,S"));
  for (std::string name; std::getline(list, name, ',');) {
    const auto c = parse_criterion(name);
    if (!c) throw UsageError("--criteria takes a list of D, A, E, S, got '" + name + "'");
    criteria.push_back(*c);
  }
  const int starts = static_cast<int>(args.integer("starts", 0, 1, 1000000));
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 1LL << 62));
  const auto out_file = args.value("out");
  if (!args.positionals().empty()) throw UsageError("unexpected positional argument");
  std::ofstream file;
  if (out_file) {
    file.open(*out_file);
    if (!file) throw InputError(*out_file, 0, "cannot write the sweep file");
    file << "criterion,positions,value,limit,ratio,starts,hits,distinct,seconds,program\n" << std::setprecision(17);
  }
  std::cout << "crit   N            value        ratio   hits/starts  distinct  seconds\n";
  for (const CriterionKind c : criteria)
    for (int n = lo; n <= hi; ++n) {
      SynthesisOptions opt;
      opt.positions = n;
      opt.criterion = c;
      opt.starts = starts;
      opt.seed = seed;
      const SynthesisResult r = synthesize(opt);
      const double limit = criterion_limit(c).value;
      std::cout << std::setw(4) << criterion_name(c) << std::setw(4) << n << std::setw(17) << std::setprecision(10)
                << r.value << std::setw(13) << std::setprecision(8) << r.value / limit << std::setw(7) << r.hits << "/"
                << std::left << std::setw(6) << r.starts << std::right << std::setw(9) << r.distinct << std::setw(9)
                << std::setprecision(3) << r.seconds
                << std::endl;
      if (file) {
        file << criterion_name(c) << "," << n << "," << r.value << "," << limit << "," << r.value / limit << ","
             << r.starts << "," << r.hits << "," << r.distinct << "," << r.seconds << ",\"";
        for (std::size_t i = 0; i < r.program.positions.size(); ++i) {
          const auto& p = r.program.positions[i];
          file << (i ? ";" : "") << p(0) << " " << p(1) << " " << p(2);
        }
        file << "\"" << std::endl;
      }
    }
  return 0;
}

const Registration reg({"sweep", "sweep --positions 9..40 --criteria D,A,E,S [--starts K] [--seed S] [--out FILE]",
                        "the best program for every N and criterion, and its ratio to the N -> infinity limit", 42, run});

}  // namespace
}  // namespace scalcal::cli
