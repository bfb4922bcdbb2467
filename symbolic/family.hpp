// Families of calibration programs with exact coordinates, discovered by name. A family is one
// file in symbolic/families/ defining `Family NAME_family()` plus one line in family_list.cpp.
// Parameter values are GiNaC expressions: numbers give numbers, names give closed forms in them.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/program/program.hpp"
#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

struct FamilyParam {
  std::string key;
  std::string fallback;  // default value, as text
  std::string doc;
};

using ParamMap = std::map<std::string, GiNaC::ex>;

struct FamilyInstance {
  GiNaC::ex N;       // number of positions (a closed form when multiplicities are symbols)
  GiNaC::matrix M;   // H^T H of the paper's model, exact
  MomentFunction moment;  // any moment of the program, for the other models (--model)
};

struct Family {
  std::string name;
  std::string summary;
  std::vector<FamilyParam> params;
  std::function<FamilyInstance(const ParamMap&)> instance;
  // The same program built by numeric/program.hpp (for cross-checks); nullopt when a parameter
  // is symbolic.
  std::function<std::optional<Program>(const ParamMap&)> numeric;
};

const std::vector<Family>& families();

// Throws InputError for an unknown name.
const Family& find_family(const std::string& name);

// Parses "key=value" settings against the family's parameters (defaults filled in). One symbol
// table serves all values, so the same name means the same symbol. Throws InputError.
ParamMap parse_params(const Family& family, const std::vector<std::string>& settings);

// A parameter that must be a number: an integer in [lo, hi] (throws InputError otherwise).
int integer_param(const ParamMap& p, const std::string& key, int lo, int hi);
// True when the value holds no symbol.
bool is_number(const GiNaC::ex& e);

}  // namespace scalcal::symbolic
