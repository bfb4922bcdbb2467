// The catalogue of named programs, each with its source in the paper, and the resolution of a
// PROGRAM argument (a catalogue name, a parametric name such as rotation-8-p15, or a CSV file).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "numeric/program/program.hpp"

namespace scalcal {

struct CatalogueEntry {
  std::string name;
  std::string description;
  std::string source;  // where the paper (or its references) gives this program
  Program program;
};

// Every listed program. Parametric families have many more members than are listed here.
std::vector<CatalogueEntry> catalogue();

// Parametric names: classic18, rotation-K[-pDEG], octahedral-A-E-D, nine-2axes, nine-3axes,
// dodecahedral-12, icosahedral-20, table1-A, table2-E, table3-S, random-N[-sSEED].
// Returns nullopt for a name that is no catalogue name; throws InputError for a malformed one.
std::optional<Program> named_program(const std::string& name);

// A catalogue name, or else a CSV file path; throws InputError when it is neither.
Program resolve_program(const std::string& argument);

// Folder of the paper's Tables 1-3 (data/); SCALCAL_DATA in the environment overrides it.
std::string data_dir();

}  // namespace scalcal
