// The shared state of one `scalcal reproduce` run (context.hpp).
#include "experiments/reproduce/context.hpp"

#include <thread>

namespace scalcal::reproduce {

Entry make_entry(std::string family, std::string name, std::string source, Program program) {
  Entry e{std::move(family), std::move(name), std::move(source), std::move(program), {}, 0, 0, 0.0};
  e.ev = evaluate(e.program);
  return e;
}

const Entry* Context::optimum(CriterionKind c, int n) const {
  const auto it = optimised.find({c, n});
  return it == optimised.end() ? nullptr : &it->second;
}

std::vector<int> Context::optimised_sizes(CriterionKind c) const {
  std::vector<int> out;
  for (const auto& [key, e] : optimised)
    if (key.first == c) out.push_back(key.second);
  return out;
}

int Context::threads() const {
  if (options.threads > 0) return options.threads;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

}  // namespace scalcal::reproduce
