// NumPy arrays as the tables scalcal's readers check: each column becomes a CsvTable column and
// row i its line i + 1, so a bad value gets the same message as in a CSV file ("positions:3: ...",
// rows counted from 1). Shapes are checked first (ValueError naming the argument).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

#include "numeric/io/csv_table.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::python {

using Column = std::pair<std::string, pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>>;

// An (M, k) argument as k named columns; k = names.size(). ValueError unless its shape is (M, k).
std::vector<Column> columns_of(const std::string& argument, pybind11::handle array,
                               const std::vector<std::string>& names);
// An (M,) argument as one column; ValueError unless its length is `rows`.
Column column_of(const std::string& argument, pybind11::handle array, const std::string& name, pybind11::ssize_t rows);

// InputError for a NaN or infinite entry unless nonfinite_allowed (a raw log's dropouts).
CsvTable table_of(const std::string& name, const std::vector<Column>& columns, bool nonfinite_allowed);

// An (N, 3) array of directions (normalised as a program file's are), or a catalogue name or CSV path.
Program program_of(pybind11::handle positions, const std::string& name);

}  // namespace scalcal::python
