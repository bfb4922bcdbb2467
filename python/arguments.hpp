// A Python call's arguments as a command's checked Values: positional arguments fill the table's
// positional options in order, keywords its other options by their Python names (--seed: seed,
// --threshold-factor: threshold_factor); each value must have its option's Python type (int for an
// integer, int or float for a number, str or os.PathLike for a text, bool for a switch, a str or a
// sequence of str for a repeated option, and for a program also an (N, 3) array of directions).
// A wrong keyword is a TypeError, a wrong type or value a UsageError naming the argument.
#pragma once
#include <pybind11/pybind11.h>

#include "commands/core/values.hpp"

namespace scalcal::python {

commands::Values arguments(const commands::CommandTable& table, const pybind11::tuple& args,
                           const pybind11::dict& kwargs);

}  // namespace scalcal::python
