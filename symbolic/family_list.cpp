// The registry of families: adding a family adds one X(name) line here (see ADDING_A_FAMILY.md).
#include <stdexcept>

#include "numeric/io/input_error.hpp"
#include "symbolic/family.hpp"

#define SCALCAL_FAMILY_LIST(X) \
  X(octahedral)                \
  X(rotation)                  \
  X(dodecahedral)              \
  X(icosahedral)

namespace scalcal::symbolic {

#define SCALCAL_DECLARE(name) Family name##_family();
SCALCAL_FAMILY_LIST(SCALCAL_DECLARE)
#undef SCALCAL_DECLARE

const std::vector<Family>& families() {
#define SCALCAL_MAKE(name) name##_family(),
  static const std::vector<Family> all = {SCALCAL_FAMILY_LIST(SCALCAL_MAKE)};
#undef SCALCAL_MAKE
  return all;
}

const Family& find_family(const std::string& name) {
  std::string known;
  for (const auto& f : families()) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  throw InputError("family", 0, "unknown family '" + name + "' (known: " + known + ")");
}

bool is_number(const GiNaC::ex& e) {
  return GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(e));
}

ParamMap parse_params(const Family& family, const std::vector<std::string>& settings) {
  GiNaC::parser reader;
  ParamMap out;
  auto read = [&](const std::string& key, const std::string& text) {
    try {
      out[key] = reader(text);
    } catch (const std::exception& e) {
      throw InputError("--param", 0, key + "=" + text + ": not an expression (" + e.what() + ")");
    }
  };
  for (const auto& p : family.params) read(p.key, p.fallback);
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--param", 0, "expected key=value, got '" + s + "'");
    const std::string key = s.substr(0, eq);
    bool known = false;
    for (const auto& p : family.params) known = known || p.key == key;
    if (!known) throw InputError("--param", 0, "family " + family.name + " has no parameter '" + key + "'");
    read(key, s.substr(eq + 1));
  }
  return out;
}

int integer_param(const ParamMap& p, const std::string& key, int lo, int hi) {
  const GiNaC::ex v = p.at(key);
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_integer())
    throw InputError("--param", 0, key + " must be an integer");
  const long n = GiNaC::ex_to<GiNaC::numeric>(v).to_long();
  if (n < lo || n > hi)
    throw InputError("--param", 0, key + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(n);
}

}  // namespace scalcal::symbolic
