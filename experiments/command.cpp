#include "experiments/command.hpp"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace scalcal::cli {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> r;
  return r;
}
}  // namespace

Registration::Registration(Command c) {
  auto& r = registry();
  r.push_back(std::move(c));
  std::stable_sort(r.begin(), r.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
}

const std::vector<Command>& commands() { return registry(); }

bool progress_enabled() { return isatty(STDERR_FILENO) != 0; }

bool Args::flag(const std::string& name) {
  const auto it = std::find(tokens_.begin(), tokens_.end(), "--" + name);
  if (it == tokens_.end()) return false;
  tokens_.erase(it);
  return true;
}

std::vector<std::string> Args::values(const std::string& name) {
  std::vector<std::string> out;
  const std::string key = "--" + name;
  for (std::size_t i = 0; i < tokens_.size();) {
    if (tokens_[i] == key) {
      if (i + 1 >= tokens_.size()) throw UsageError("option " + key + " needs a value");
      out.push_back(tokens_[i + 1]);
      tokens_.erase(tokens_.begin() + static_cast<long>(i), tokens_.begin() + static_cast<long>(i) + 2);
    } else if (tokens_[i].rfind(key + "=", 0) == 0) {
      out.push_back(tokens_[i].substr(key.size() + 1));
      tokens_.erase(tokens_.begin() + static_cast<long>(i));
    } else {
      ++i;
    }
  }
  return out;
}

std::optional<std::string> Args::value(const std::string& name) {
  auto v = values(name);
  if (v.empty()) return std::nullopt;
  if (v.size() > 1) throw UsageError("option --" + name + " given more than once");
  return v.front();
}

std::string Args::text(const std::string& name, const std::string& fallback) {
  return value(name).value_or(fallback);
}

long long Args::integer(const std::string& name, long long fallback, long long lo, long long hi) {
  const auto v = value(name);
  if (!v) return fallback;
  long long x = 0;
  std::size_t used = 0;
  try {
    x = std::stoll(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != v->size())
    throw UsageError("option --" + name + " takes an integer, got '" + *v + "'");
  if (x < lo || x > hi)
    throw UsageError("option --" + name + " must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                     ", got " + *v);
  return x;
}

double Args::real(const std::string& name, double fallback) {
  const auto v = value(name);
  if (!v) return fallback;
  double x = 0;
  std::size_t used = 0;
  try {
    x = std::stod(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != v->size() || !std::isfinite(x))
    throw UsageError("option --" + name + " takes a finite number, got '" + *v + "'");
  return x;
}

std::vector<std::string> Args::positionals() {
  for (const auto& t : tokens_)
    if (t.size() > 2 && t.rfind("--", 0) == 0) throw UsageError("unknown option " + t);
  return tokens_;
}

}  // namespace scalcal::cli
