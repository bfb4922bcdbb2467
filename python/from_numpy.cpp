// NumPy arrays as the tables scalcal's readers check (from_numpy.hpp).
#include "python/from_numpy.hpp"

#include <cmath>
#include <sstream>

#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/program/program_csv.hpp"

namespace py = pybind11;

namespace scalcal::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& a) {
  std::ostringstream s;
  s << "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s << (d ? ", " : "") << a.shape(d);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

Array as_array(const std::string& argument, py::handle value) {
  Array a = Array::ensure(value);  // NumPy's conversion; a null array (error cleared) when impossible
  if (!a) throw py::value_error(argument + " must be an array of numbers");
  return a;
}

}  // namespace

std::vector<Column> columns_of(const std::string& argument, py::handle value, const std::vector<std::string>& names) {
  const Array a = as_array(argument, value);
  const auto k = static_cast<py::ssize_t>(names.size());
  if (a.ndim() != 2 || a.shape(1) != k)
    throw py::value_error(argument + " must have shape (M, " + std::to_string(k) + "), got " + shape_text(a));
  std::vector<Column> out;
  for (py::ssize_t c = 0; c < k; ++c) {
    Array col(a.shape(0));
    for (py::ssize_t i = 0; i < a.shape(0); ++i) col.mutable_at(i) = a.at(i, c);
    out.emplace_back(names[static_cast<std::size_t>(c)], std::move(col));
  }
  return out;
}

Column column_of(const std::string& argument, py::handle value, const std::string& name, py::ssize_t rows) {
  const Array a = as_array(argument, value);
  if (a.ndim() != 1 || a.shape(0) != rows)
    throw py::value_error(argument + " must have shape (" + std::to_string(rows) + ",), got " + shape_text(a));
  return {name, a};
}

CsvTable table_of(const std::string& name, const std::vector<Column>& columns, bool nonfinite_allowed) {
  CsvTable t;
  t.file = name;
  const py::ssize_t rows = columns.empty() ? 0 : columns.front().second.shape(0);
  for (const auto& c : columns) {
    // As the CSV reader refuses a header naming one column twice (compared without case: IX and ix).
    if (t.column(c.first) >= 0)
      throw InputError(name, 0, "column '" + c.first + "' appears twice (column names are compared without case)");
    t.columns.push_back(c.first);
  }
  for (py::ssize_t i = 0; i < rows; ++i) {
    CsvTable::Row row;
    row.line = static_cast<int>(i + 1);
    for (const auto& c : columns) {
      const double v = c.second.at(i);
      if (!std::isfinite(v) && !nonfinite_allowed)
        throw InputError(name, row.line, "value in column " + c.first + " is not finite (" + std::to_string(v) + ")");
      row.values.push_back(v);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

Program program_of(py::handle positions, const std::string& name) {
  if (py::isinstance<py::str>(positions)) return resolve_program(positions.cast<std::string>());
  return program_from_table(table_of(name, columns_of(name, positions, {"x", "y", "z"}), false));
}

}  // namespace scalcal::python
