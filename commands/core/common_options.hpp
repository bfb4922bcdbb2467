// Options several commands share, written once with one text, range and help line everywhere, and
// the typed reading of their values.
#pragma once
#include <string>
#include <vector>

#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/synthesis/local_result.hpp"

namespace scalcal::commands {

struct IntegerRange {
  long long lo, hi;
};
inline constexpr IntegerRange kSeeds{0, 1LL << 62}, kStarts{1, 1000000}, kThreads{0, 256};

std::vector<std::string> criterion_names();  // the registry's, in its order
std::vector<std::string> model_names();
std::vector<std::string> local_solver_names();        // auto, newton, lbfgs, ipopt
std::string criterion_names_text();                   // "D, A, E, S"
std::string shortest_text(double x);                  // the shortest text that reads back to x ("0.5")
LogFormat log_format_named(const std::string& name);  // --format's choice (auto, csv, text)

// --criterion: every registered criterion, with its normalised form in the help ("D = N^9 det K").
Option criterion_option(const std::string& fallback = "D");
Option model_option();  // --model, default paper9
// --model that also takes a thermal model, BASE+Tk or BASE+bias:Tk (numeric/thermal/thermal_model.hpp)
Option model_or_thermal_option();
Option temperature_option();  // --temperature T1..T2 (degrees Celsius), the range a thermal model spans
Option region_option();       // --region SPEC, repeatable (their union)
Option tolerance_option();    // --tolerance DEG: how far outside the region a position still counts as inside
Option seed_option();         // --seed, default 1
Option starts_option();       // --starts, default adaptive
Option threads_option();      // --threads, default 0 = all cores
Option local_option();        // --local auto|newton|lbfgs|ipopt
Option program_argument(const std::string& what = "");  // PROGRAM: a catalogue name or a CSV file
Option json_option(const std::string& what);            // --json (the CLI's output form)
Option out_option(const std::string& what, const std::string& value_name = "FILE");  // --out (the CLI writes it)

Option integer_option(std::string name, long long lo, long long hi, std::string what, std::string unit,
                      std::string fallback, std::string fallback_text = "");
Option number_option(std::string name, double low, double high, std::string what, std::string unit,
                     std::string fallback);
Option positive_option(std::string name, std::string what, std::string unit, std::string fallback);
Option text_option(std::string name, std::string value_name, std::string what, std::string unit = "none",
                   std::string fallback = "");
Option choice_option(std::string name, std::vector<std::string> choices, std::string what, std::string fallback);
Option flag_option(std::string name, std::string what);
Option named(Option option, std::string value_name);
Option positions_option(Option option);  // a program option: Python may give an (N, 3) array too  // the option shown
                                         // as `--name VALUE_NAME` in usage lines

CriterionKind criterion_of(const Values& values, const std::string& option = "--criterion");
ModelKind model_of(const Values& values);
LocalSolver local_solver_of(const Values& values);

// The PROGRAM argument: positions given as data (Values::program), else a catalogue name or a CSV file.
Program program_of(const Values& values, const std::string& option = "PROGRAM");

}  // namespace scalcal::commands
