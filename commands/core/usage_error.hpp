// Errors of a request, as opposed to its data (InputError, numeric/io/input_error.hpp): options that
// contradict each other or that the chosen model does not take. The CLI exits 2 with "(see `scalcal
// COMMAND --help`)"; Python raises scalcal.UsageError.
#pragma once
#include <stdexcept>

namespace scalcal {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace scalcal
