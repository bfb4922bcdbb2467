// One synthesis's starts run ahead on other MPI ranks (sweep_starts.hpp).
#include "commands/research/sweep_starts.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "numeric/synthesis/stopping_rule.hpp"

namespace scalcal::commands {
namespace {

void put(std::string& out, double x) {
  char text[40];
  std::snprintf(text, sizeof text, " %a", x);
  out += text;
}

double take_double(std::istringstream& in) {
  std::string word;
  if (!(in >> word)) throw std::invalid_argument("a start cut short");
  char* end = nullptr;
  const double x = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size()) throw std::invalid_argument("'" + word + "' is not a number");
  return x;
}

template <class Int>
Int take_int(std::istringstream& in) {
  Int x{};
  if (!(in >> x)) throw std::invalid_argument("a start cut short");
  return x;
}

}  // namespace

std::vector<StartRange> start_ranges(const Sweep& sweep) {
  const int batch = StoppingRule{}.batch;
  std::vector<StartRange> out;
  for (std::size_t k = 0; k < sweep.tasks().size(); ++k) {
    const int certain = sweep.certain_starts(sweep.tasks()[k]);
    if (certain <= batch) continue;
    for (int first = 0; first < certain; first += batch) out.push_back({k, first, std::min(batch, certain - first)});
  }
  return out;
}

std::string starts_line(const StartRange& range, const std::vector<LocalResult>& results) {
  std::string out = std::to_string(range.task) + " " + std::to_string(range.first) + " " + std::to_string(range.count);
  for (const LocalResult& r : results) {
    out += " " + std::to_string(static_cast<int>(r.summary.termination)) + " " + std::to_string(r.summary.iterations);
    put(out, r.value);
    for (const Vec3& p : r.program.positions)
      for (int c = 0; c < 3; ++c) put(out, p(c));
  }
  return out;
}

StartsLine read_starts_line(const Sweep& sweep, const std::string& line) {
  std::istringstream in(line);
  StartsLine out;
  out.range.task = take_int<std::size_t>(in);
  out.range.first = take_int<int>(in);
  out.range.count = take_int<int>(in);
  if (out.range.task >= sweep.tasks().size() || out.range.first < 0 || out.range.count <= 0)
    throw std::invalid_argument("not a range of starts of the sweep's tasks");
  const int positions = sweep.tasks()[out.range.task].positions;
  for (int s = 0; s < out.range.count; ++s) {
    LocalResult r;
    r.summary.termination = static_cast<Termination>(take_int<int>(in));
    r.summary.iterations = take_int<int>(in);
    r.value = take_double(in);
    for (int i = 0; i < positions; ++i) {
      const double x = take_double(in), y = take_double(in), z = take_double(in);
      r.program.positions.emplace_back(x, y, z);
    }
    out.results.push_back(std::move(r));
  }
  std::string rest;
  if (in >> rest) throw std::invalid_argument("more starts than the range holds");
  return out;
}

std::vector<std::vector<LocalResult>> known_starts(const Sweep& sweep, const std::vector<std::string>& texts) {
  std::vector<std::map<int, std::vector<LocalResult>>> ranges(sweep.tasks().size());
  for (const std::string& text : texts) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      StartsLine l = read_starts_line(sweep, line);
      ranges[l.range.task][l.range.first] = std::move(l.results);
    }
  }
  std::vector<std::vector<LocalResult>> out(sweep.tasks().size());
  for (std::size_t k = 0; k < out.size(); ++k)
    for (auto& [first, results] : ranges[k]) {
      if (first != static_cast<int>(out[k].size())) break;
      out[k].insert(out[k].end(), results.begin(), results.end());
    }
  return out;
}

}  // namespace scalcal::commands
