// What a subcommand computes, apart from how it is shown: the object of its --json and its readable
// text. The CLI prints one of the two; the Python module (python/) returns the object, so both give
// the same numbers from the same code.
#pragma once
#include <string>

#include "experiments/cli/json_output.hpp"

namespace scalcal::cli {

struct Report {
  Json json;
  std::string text;
  int status = 0;  // the CLI's exit status (1: calibrate did not converge)
};

// Prints the JSON object (json) or the text to stdout; returns the status.
int print_report(const Report& report, bool json);

}  // namespace scalcal::cli
