// Families of calibration programs with exact coordinates, discovered by file. A family is one
// file in symbolic/families/ defining `std::vector<Family> FILE_families()` (FILE its name without
// .cpp); the build lists the folder, so `family`, `evaluate`, `catalogue`, `optimize --from`, `augment`,
// `polish`, `certify` and the reproduction find it with no other edit (ADDING_A_FAMILY.md).
// Parameter values are GiNaC expressions: numbers give numbers, names give closed forms in them.
#pragma once
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/program/program.hpp"
#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

// Symbols across all parameters of a family: the exact criteria's cost grows steeply with them
// (octahedral: 5 symbols 0.5 s, 6 symbols 3.7 s, 8 symbols 23 s, 12 over 60 s and 1.7 GB).
inline constexpr int kMaxFamilySymbols = 6;

struct FamilyParam {
  std::string key;
  std::string fallback;  // default value, as text
  std::string doc;
  // How the text of a value becomes an expression; empty: GiNaC's parser (numbers and symbols).
  std::function<GiNaC::ex(const std::string& text, GiNaC::parser& reader)> read = {};
  // The most distinct symbols this parameter may hold: exact forms grow fast with symbols (docs/family.md).
  int max_symbols = kMaxFamilySymbols;
};

using ParamMap = std::map<std::string, GiNaC::ex>;

struct FamilyInstance {
  GiNaC::ex N;            // number of positions (a closed form when multiplicities are symbols)
  GiNaC::matrix M;        // H^T H of the paper's model, exact
  MomentFunction moment;  // any moment of the program, for the other models (--model)
};

struct Family {
  std::string name;
  std::string summary;
  std::vector<FamilyParam> params;
  // Program names of this family: literal text with {key} for a parameter given as a number
  // ("octa-{k}"); any parameter may also follow as @key=value ("jig:cube@orientation=aa:0,0,1,30").
  // Empty: the family has no program names of its own (the paper's four, whose names numeric owns).
  std::string pattern;
  std::string group = "family";    // "jig" puts it among the printable jigs of the figures and tables
  std::string source = "scalcal";  // where it comes from, for the catalogue
  // The exact positions with their multiplicities (integers for a program). A family that gives
  // them needs nothing else: instance and numeric below are derived when left empty.
  std::function<std::vector<WeightedPoint>(const ParamMap&)> points;
  std::function<FamilyInstance(const ParamMap&)> instance;
  // The same program in double (nullopt when a parameter is symbolic): numeric/program.hpp's
  // constructor where one exists, else the exact points rounded.
  std::function<std::optional<Program>(const ParamMap&)> numeric;
};

// Every family: those of symbolic/families/ in file order, then those registered at run time.
const std::deque<Family>& families();

// Adds a family at run time (a test's own, a plug-in's), with its program names. Throws
// std::invalid_argument for a name already taken.
void register_family(Family family);

// Registers every family's program names with numeric's registry (numeric/program/program_names.hpp);
// front ends (the CLI, the Python module) call it once at start. Idempotent.
void register_family_programs();

// Throws InputError for an unknown name.
const Family& find_family(const std::string& name);

// Parses "key=value" settings against the family's parameters (defaults filled in). One symbol
// table serves all values, so the same name means the same symbol. Throws InputError.
ParamMap parse_params(const Family& family, const std::vector<std::string>& settings);

// A parameter that must be a number: an integer in [lo, hi] (throws InputError otherwise).
int integer_param(const ParamMap& p, const std::string& key, int lo, int hi);
// True when the value holds no symbol (a list: when none of its elements does).
bool is_number(const GiNaC::ex& e);
// A value as text for output: canonical_text, a list as {a,b,...}.
std::string param_text(const GiNaC::ex& e);

// Exact points with integer multiplicities as a program in double (each point repeated).
Program rounded_program(const std::vector<WeightedPoint>& points);

}  // namespace scalcal::symbolic
