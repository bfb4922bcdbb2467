// `scalcal family` as a function: the exact criteria of a family member (closed forms from
// symbolic/, numbers from them), or closed forms in symbolic parameters, for the paper's model or any
// registered model. Every expression is canonical text (symbolic::canonical_text): equal runs, equal bytes.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::commands {

struct FamilyRequest {
  std::string name;                 // the family
  std::vector<std::string> params;  // KEY=VALUE
  ModelKind model = ModelKind::paper9;
};

// One criterion or theta: its closed form (or why there is none) and its number when it has one.
struct ExactRow {
  std::string key;    // "D", ..., "theta_bias"
  bool exact = true;  // false: no closed form (an eigenvalue of an irregular block)
  std::string text;   // canonical text, "max(c1, c2)" while symbols leave the order open
  std::optional<double> number;
};

struct FamilyResult {
  std::string family;
  std::vector<std::pair<std::string, std::string>> params;  // key, canonical text
  ModelKind model = ModelKind::paper9;
  std::string positions;                  // N, exact text
  std::optional<double> positions_value;  // N as a number; none when symbolic
  bool positions_integer = false;
  std::vector<ExactRow> rows;  // every registered criterion with a closed form, then the model's thetas
  Warnings warnings;
};

// NAME [--param KEY=VALUE]... [--model NAME] [--json]
const CommandTable& family_table();
FamilyRequest family_request(const Values& values);

// Throws InputError for an unknown family or parameter, a singular member, or symbolic parameters
// without closed forms.
FamilyResult family(const FamilyRequest& request);

Json to_json(const FamilyResult& result);

}  // namespace scalcal::commands
