// Printing the results' JSON (json_output.hpp).
#include "experiments/cli/json_output.hpp"

#include <iostream>

namespace scalcal::cli {

void print_json(const Json& j) { write_json(std::cout, j); }
void write_json(std::ostream& out, const Json& j) { out << json_text(j, 2) << "\n"; }

}  // namespace scalcal::cli
