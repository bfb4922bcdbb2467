// A report's JSON object as Python values: objects become dicts (keys in the CLI's order), arrays
// of numbers and rectangular arrays of such arrays become NumPy arrays (int64 when every entry is
// an integer, float64 otherwise), null becomes None. Everything else keeps its JSON type.
#pragma once
#include <pybind11/pybind11.h>

#include "commands/core/json.hpp"

namespace scalcal::python {

pybind11::object to_python(const commands::Json& value);

}  // namespace scalcal::python
