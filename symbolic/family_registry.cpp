// The registry of families: the files of symbolic/families/ (listed by the build into
// family_files.inc, one X(FILE) each) and those registered at run time, and their program names
// in numeric's registry.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <regex>
#include <set>
#include <stdexcept>

#include <cln/integer.h>

#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/program/program_names.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"

namespace scalcal::symbolic {

#define X(file) std::vector<Family> file##_families();
#include "family_files.inc"
#undef X

namespace {

// Fills what a family that gives its points leaves out.
Family completed(Family f) {
  if (f.points && !f.instance)
    f.instance = [points = f.points](const ParamMap& p) {
      const auto pts = points(p);
      GiNaC::ex n = 0;
      for (const auto& w : pts) n += w.weight;
      return FamilyInstance{GiNaC::expand(n), moment_matrix(pts), point_moments(pts)};
    };
  if (f.points && !f.numeric)
    f.numeric = [points = f.points](const ParamMap& p) -> std::optional<Program> {
      for (const auto& [k, v] : p)
        if (!is_number(v)) return std::nullopt;
      return rounded_program(points(p));
    };
  return f;
}

struct Store {
  std::mutex mutex;
  std::deque<Family> all;
  Store() {
#define X(file) \
  for (auto& f : file##_families()) all.push_back(completed(std::move(f)));
#include "family_files.inc"
#undef X
  }
};

Store& store() {
  static Store s;
  return s;
}

// A parameter value inside a program name: a decimal or a fraction, signed.
constexpr const char* kNumberInName = R"((-?[0-9]+(?:\.[0-9]+)?(?:/[0-9]+)?))";
constexpr std::size_t kMaxNameLength = 200;

std::string regex_escaped(const std::string& s) {
  static const std::string special = R"(\^$.|?*+()[]{}/)";
  std::string out;
  for (char c : s) {
    if (special.find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t from = 0;
  for (std::size_t at; (at = s.find(sep, from)) != std::string::npos; from = at + 1)
    parts.push_back(s.substr(from, at - from));
  parts.push_back(s.substr(from));
  return parts;
}

// The resolver of a family's program names: the pattern's literal text with a number at each {key},
// then any @key=value.
std::function<std::optional<Program>(const std::string&)> name_resolver(const Family& family) {
  std::string re;
  std::vector<std::string> keys;
  const std::string& pat = family.pattern;
  for (std::size_t i = 0; i < pat.size();) {
    if (pat[i] == '{') {
      const std::size_t close = pat.find('}', i);
      if (close == std::string::npos) throw std::invalid_argument("family " + family.name + ": unclosed { in pattern");
      keys.push_back(pat.substr(i + 1, close - i - 1));
      re += kNumberInName;
      i = close + 1;
    } else {
      const std::size_t next = pat.find('{', i);
      re += regex_escaped(pat.substr(i, next == std::string::npos ? std::string::npos : next - i));
      i = next == std::string::npos ? pat.size() : next;
    }
  }
  const std::string family_name = family.name;
  return [re = std::regex(re), keys, family_name](const std::string& name) -> std::optional<Program> {
    if (name.size() > kMaxNameLength) return std::nullopt;
    const std::size_t at = name.find('@');
    const std::string base = name.substr(0, at);
    std::smatch m;
    if (!std::regex_match(base, m, re)) return std::nullopt;
    // @key=value overrides the pattern's value of key (testcubo-1@copies=3); the same @key twice is refused
    // by parse_params, as a repeated --param is.
    std::vector<std::string> overrides;
    if (at != std::string::npos)
      for (const auto& s : split(name.substr(at + 1), '@')) {
        // A name is a number's text, not a computation: GiNaC evaluates powers and factorials of
        // numbers eagerly, and 9^9^9 would take the machine's memory.
        if (s.find_first_of("^!") != std::string::npos)
          throw InputError(name, 0,
                           "'" + display_name(s) + "': powers (^) and factorials (!) are not taken in a program name");
        overrides.push_back(s);
      }
    std::vector<std::string> settings;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const bool overridden = std::any_of(overrides.begin(), overrides.end(),
                                          [&](const std::string& o) { return o.rfind(keys[k] + "=", 0) == 0; });
      if (!overridden) settings.push_back(keys[k] + "=" + m[k + 1].str());
    }
    settings.insert(settings.end(), overrides.begin(), overrides.end());
    const Family& f = find_family(family_name);
    std::optional<Program> p;
    try {
      const ParamMap params = parse_params(f, settings);
      for (const auto& [k, v] : params)
        if (!is_number(v)) throw InputError("", 0, k + " must be a number in a program name, not " + param_text(v));
      p = f.numeric(params);
    } catch (const InputError& e) {
      throw InputError(name, 0, e.reason());
    } catch (const std::exception& e) {  // GiNaC's, or a family's own invalid_argument
      throw InputError(name, 0, std::string("not a program of family ") + family_name + " (" + e.what() + ")");
    }
    if (!p) throw InputError(name, 0, "family " + family_name + " gives no numeric program for these parameters");
    if (p->size() < 1 || p->size() > kMaximumPositions)
      throw InputError(
          name, 0, std::to_string(p->size()) + " positions; a program holds 1.." + std::to_string(kMaximumPositions));
    return p;
  };
}

void register_names(const Family& f) {
  if (f.pattern.empty()) return;
  ProgramNames names;
  names.key = "family:" + f.name;
  names.pattern = f.pattern;
  names.group = f.group;
  names.resolve = name_resolver(f);
  if (f.pattern.find('{') == std::string::npos) names.listed.push_back({f.pattern, f.summary, f.source});
  register_program_names(std::move(names));
}

}  // namespace

const std::deque<Family>& families() { return store().all; }

void register_family(Family family) {
  Store& s = store();
  {
    const std::lock_guard<std::mutex> lock(s.mutex);
    for (const auto& f : s.all)
      if (f.name == family.name) throw std::invalid_argument("register_family: the name " + f.name + " is taken");
    s.all.push_back(completed(std::move(family)));
  }
  register_names(s.all.back());
}

void register_family_programs() {
  for (const auto& f : families()) register_names(f);
}

const Family& find_family(const std::string& name) {
  std::string known;
  for (const auto& f : families()) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  throw InputError("family", 0, "unknown family '" + display_name(name) + "' (known: " + known + ")");
}

bool is_number(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::lst>(e) || GiNaC::is_a<GiNaC::matrix>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!is_number(e.op(i))) return false;
    return true;
  }
  const GiNaC::ex v = GiNaC::evalf(e);
  return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real();
}

std::string param_text(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    const auto& m = GiNaC::ex_to<GiNaC::matrix>(e);
    std::string s = "[";
    for (unsigned r = 0; r < m.rows(); ++r) {
      s += r ? ",[" : "[";
      for (unsigned c = 0; c < m.cols(); ++c) s += (c ? "," : "") + canonical_text(m(r, c));
      s += "]";
    }
    return s + "]";
  }
  if (GiNaC::is_a<GiNaC::lst>(e)) {
    std::string s = "{";
    for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? "," : "") + param_text(e.op(i));
    return s + "}";
  }
  return canonical_text(e);
}

namespace {

// GiNaC evaluates a number raised to a number at once, exactly: 2^(2^40) would take gigabytes before
// any range check. So an exponent must be a plain number of at most kMaxExponent in size, or an
// expression without numbers raised to numbers inside it (a symbol, sqrt's 1/2).
constexpr double kMaxExponent = 1000;

// A decimal literal's own exponent, 0E555555555, is computed exactly too (10^555555555: 19 s, and
// 12x longer for each further digit; the fuzzer found it), so it has the same bound. An identifier
// that ends in digits and 'e' (x1e5) is not a literal and is left to the parser.
void check_decimal_exponents(const std::string& key, const std::string& text) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  for (std::size_t at = 0; at < text.size(); ++at) {
    if ((text[at] != 'e' && text[at] != 'E') || at == 0 || !(digit(text[at - 1]) || text[at - 1] == '.')) continue;
    std::size_t start = at;
    while (start > 0 && (digit(text[start - 1]) || text[start - 1] == '.')) --start;
    if (start > 0 && (std::isalpha(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '_')) continue;
    std::size_t b = at + 1;
    if (b < text.size() && (text[b] == '+' || text[b] == '-')) ++b;
    std::size_t e = b;
    while (e < text.size() && text[e] == '0') ++e;  // leading zeros say nothing of the size
    std::size_t end = e;
    while (end < text.size() && digit(text[end])) ++end;
    if (end - e > 4 || (end > e && std::stoi(text.substr(e, end - e)) > kMaxExponent))
      throw InputError("--param", 0,
                       key + "=" + display_name(text) + ": a decimal exponent above " +
                           std::to_string(int(kMaxExponent)) + " (the number would be computed exactly)");
  }
}

// GiNaC's parser matches a call without arguments, sqrt(), to the function of any arity (its prototype
// order treats 0 arguments as "unspecified") and then reads the missing first argument: a null pointer
// (the fuzzer found it; GiNaC 1.8). An empty pair of parentheses is never an expression, so it is refused
// before the parser sees it.
void check_empty_calls(const std::string& key, const std::string& text) {
  for (std::size_t at = text.find('('); at != std::string::npos; at = text.find('(', at + 1)) {
    std::size_t next = at + 1;
    while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
    if (next < text.size() && text[next] == ')')
      throw InputError("--param", 0,
                       key + "=" + display_name(text) + ": empty parentheses (a function needs its argument)");
  }
}

void check_exponents(const std::string& key, const std::string& text) {
  check_empty_calls(key, text);
  check_decimal_exponents(key, text);
  for (std::size_t at = text.find('^'); at != std::string::npos; at = text.find('^', at + 1)) {
    std::size_t b = text.find_first_not_of(" \t", at + 1);
    if (b == std::string::npos) return;                        // the parser reports the syntax error
    std::size_t e = text.find_first_of("+-*/^(), \t", b + 1);  // the end of a plain atom (2^1001)
    e = e == std::string::npos ? text.size() - 1 : e - 1;
    if (text[b] == '(') {
      int depth = 0;
      for (e = b; e < text.size(); ++e) {
        depth += text[e] == '(' ? 1 : text[e] == ')' ? -1 : 0;
        if (depth == 0) break;
      }
      const std::string inner = text.substr(b + 1, e > b ? e - b - 1 : 0);
      if (inner.find('^') != std::string::npos)
        throw InputError("--param", 0, key + "=" + display_name(text) + ": an exponent may not itself contain '^'");
    }
    const std::string exponent = text.substr(b, e - b + 1);
    const std::size_t digits = exponent.find_first_of("0123456789");
    if (digits == std::string::npos) continue;
    double value = 0;
    try {
      value = std::stod(exponent.substr(digits));
    } catch (const std::exception&) {
      continue;
    }
    if (!(std::fabs(value) <= kMaxExponent))
      throw InputError("--param", 0,
                       key + "=" + display_name(text) + ": an exponent above " + std::to_string(int(kMaxExponent)) +
                           " (the number would be computed exactly)");
  }
}

void collect_symbols(const GiNaC::ex& e, std::set<std::string>& names) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) names.insert(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), names);
}

}  // namespace

namespace {

// The functions a parameter may call: the elementary ones. GiNaC's others compute exactly as they are
// read, before any range check (factorial(100000) took 22 s and its 456574 digits reached the output;
// factorial(10^7) would run for hours).
const GiNaC::prototype_table& elementary_functions() {
  static const GiNaC::prototype_table table = [] {
    static const std::set<std::string> allowed = {"sqrt", "pow",  "power", "sin", "cos", "tan",
                                                  "asin", "acos", "atan",  "exp", "log", "abs"};
    GiNaC::prototype_table t;
    for (const auto& [prototype, reader] : GiNaC::get_default_reader())
      if (allowed.count(prototype.first)) t.insert({prototype, reader});
    return t;
  }();
  return table;
}

// The largest numerator or denominator among the numbers of e, in bits: exact forms cost the
// square of it and more (a 456574-digit factorial reached the output as it was).
long long largest_bits(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (!n.is_rational()) return 0;
    const auto bits = [](const GiNaC::numeric& integer) {
      return static_cast<long long>(cln::integer_length(The(cln::cl_I)(integer.to_cl_N())));
    };
    return std::max(bits(n.numer()), bits(n.denom()));
  }
  long long most = 0;
  for (std::size_t i = 0; i < e.nops(); ++i) most = std::max(most, largest_bits(e.op(i)));
  return most;
}

// A parameter's numbers hold at most this many decimal digits (3322 bits).
constexpr long long kMaxDigits = 1000;

}  // namespace

ParamMap parse_params(const Family& family, const std::vector<std::string>& settings) {
  GiNaC::parser reader(GiNaC::symtab(), false, elementary_functions());
  ParamMap out;
  auto read = [&](const FamilyParam& p, const std::string& text) {
    check_exponents(p.key, text);
    try {
      const GiNaC::ex typed = p.read ? p.read(text, reader) : reader(text);
      // Every family is a set of real directions: an imaginary parameter would give complex positions.
      const bool imaginary =
          GiNaC::is_a<GiNaC::numeric>(typed) ? !GiNaC::ex_to<GiNaC::numeric>(typed).is_real() : typed.has(GiNaC::I);
      if (imaginary) throw InputError("--param", 0, p.key + "=" + display_name(text) + ": not a real number");
      const GiNaC::ex value = exact_decimals(typed);
      if (const long long bits = largest_bits(value); bits > kMaxDigits * 3.3219280948873623)
        throw InputError("--param", 0,
                         p.key + "=" + display_name(text) + ": a number of about " +
                             std::to_string(static_cast<long long>(bits * 0.3010299956639812)) + " digits; at most " +
                             std::to_string(kMaxDigits) + " (the exact forms would grow with it)");
      std::set<std::string> own;
      collect_symbols(value, own);
      if (static_cast<int>(own.size()) > p.max_symbols)
        throw InputError("--param", 0,
                         p.key + "=" + display_name(text) + ": " + std::to_string(own.size()) +
                             " symbols; the exact forms take minutes to hours beyond " + std::to_string(p.max_symbols) +
                             " here (give numbers for the others)");
      out[p.key] = value;
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      // GiNaC's parser appends its own source location on a second line: one line, without it.
      const std::string what = e.what();
      throw InputError(
          "--param", 0,
          p.key + "=" + display_name(text) + ": not an expression (" + what.substr(0, what.find('\n')) + ")");
    }
  };
  for (const auto& p : family.params) read(p, p.fallback);
  std::vector<std::string> given;
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param", 0, "expected key=value, got '" + display_name(s) + "'");
    const std::string key = s.substr(0, eq);
    const FamilyParam* param = nullptr;
    for (const auto& p : family.params)
      if (p.key == key) param = &p;
    if (!param)
      throw InputError("--param", 0, "family " + family.name + " has no parameter '" + display_name(key) + "'");
    if (std::find(given.begin(), given.end(), key) != given.end())
      throw InputError("--param", 0, key + " is given twice");  // as a repeated option is refused
    given.push_back(key);
    read(*param, s.substr(eq + 1));
  }
  std::set<std::string> all;
  for (const auto& [key, value] : out) collect_symbols(value, all);
  if (static_cast<int>(all.size()) > kMaxFamilySymbols)
    throw InputError("--param", 0,
                     std::to_string(all.size()) + " distinct symbols; the exact forms take minutes to hours beyond " +
                         std::to_string(kMaxFamilySymbols) + " (6 take about 4 s; give numbers for the others)");
  return out;
}

int integer_param(const ParamMap& p, const std::string& key, int lo, int hi) {
  const GiNaC::ex v = p.at(key);
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_integer())
    throw InputError("--param", 0, key + " must be an integer");
  // Compared as exact integers: to_long() keeps only the low 64 bits (2^64 passed as 0).
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(v);
  if (n < lo || n > hi)
    throw InputError("--param", 0, key + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(n.to_int());
}

Program rounded_program(const std::vector<WeightedPoint>& points) {
  Program p;
  for (const auto& w : points) {
    if (!GiNaC::is_a<GiNaC::numeric>(w.weight) || !GiNaC::ex_to<GiNaC::numeric>(w.weight).is_integer() ||
        GiNaC::ex_to<GiNaC::numeric>(w.weight).is_negative())
      throw InputError("", 0, "a multiplicity must be a non-negative integer, not " + canonical_text(w.weight));
    if (GiNaC::ex_to<GiNaC::numeric>(w.weight) > kMaximumPositions)  // exactly, before to_long() keeps 64 bits
      throw InputError("", 0, "a multiplicity above " + std::to_string(kMaximumPositions));
    const long times = GiNaC::ex_to<GiNaC::numeric>(w.weight).to_long();
    Vec3 v;
    for (int c = 0; c < 3; ++c) {
      const GiNaC::ex x = GiNaC::evalf(w.eta[c]);
      if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real())
        throw InputError("", 0, "a coordinate is not a real number: " + canonical_text(w.eta[c]));
      v(c) = GiNaC::ex_to<GiNaC::numeric>(x).to_double();
    }
    for (long k = 0; k < times; ++k) p.positions.push_back(v);
  }
  return p;
}

}  // namespace scalcal::symbolic
