// Python arguments as Values (arguments.hpp).
#include "python/arguments.hpp"

#include <algorithm>
#include <charconv>

#include "commands/core/usage_error.hpp"
#include "numeric/io/csv_table.hpp"
#include "python/from_numpy.hpp"

namespace py = pybind11;

namespace scalcal::python {
namespace {

using commands::Option;
using commands::OptionKind;

std::string type_name(py::handle v) { return py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>(); }

[[noreturn]] void wrong_type(const Option& o, const std::string& wanted, py::handle v) {
  throw UsageError(o.python_name() + ": must be " + wanted + ", got " + type_name(v));
}

std::string shortest(double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

// A text argument: str or os.PathLike (a pathlib.Path), as the CLI would get it.
std::string text_of(const Option& o, py::handle v) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::hasattr(v, "__fspath__")) return py::str(py::module_::import("os").attr("fspath")(v)).cast<std::string>();
  wrong_type(o, "a str", v);
}

// A number as Python and NumPy spell them: int, float and their NumPy kinds (numbers.Integral and
// numbers.Real, which NumPy registers), never a bool (True is an int to Python).
bool is_bool(py::handle v) { return py::isinstance<py::bool_>(v) || type_name(v) == "bool_" || type_name(v) == "bool"; }
bool is_integral(py::handle v) {
  static const py::object integral = py::module_::import("numbers").attr("Integral");
  return !is_bool(v) && py::isinstance(v, integral);
}
bool is_real(py::handle v) {
  static const py::object real = py::module_::import("numbers").attr("Real");
  return !is_bool(v) && py::isinstance(v, real);
}

// An integral number as its exact decimal text (operator.index: NumPy's integers too, and a Python int
// of any size, which the option's range then refuses by name); a real one as the shortest text of its
// double (a float32 widened exactly).
std::string number_text(py::handle v) {
  if (is_integral(v)) return py::str(py::module_::import("operator").attr("index")(v)).cast<std::string>();
  return shortest(py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>());
}

std::string value_text(const Option& o, py::handle v) {
  switch (o.kind) {
    case OptionKind::integer:
      if (!is_integral(v)) wrong_type(o, "an int", v);
      return number_text(v);
    case OptionKind::number:
      if (!is_real(v)) wrong_type(o, "a number", v);
      return number_text(v);
    default:
      // A number where the option takes text (--magnitude 9.81|auto) is written as the CLI would read it.
      if (is_real(v)) return number_text(v);
      return text_of(o, v);
  }
}

// A data file given as a mapping column name -> 1-D array, as a CSV file would give it (rows from 1);
// dropouts (NaN) are kept for the reader to count, as a raw log's are.
CsvTable table_of_columns(const std::string& argument, const py::dict& columns) {
  std::vector<Column> cols;
  py::ssize_t rows = -1;
  for (const auto& [key, value] : columns) {
    const std::string name = py::str(key).cast<std::string>();
    if (rows < 0) rows = py::len(value);
    cols.push_back(column_of(argument + "[" + name + "]", value, name, rows));
  }
  if (cols.empty()) throw UsageError(argument + ": must name at least one column");
  return table_of(argument, cols, true);
}

void set(commands::Values& values, const Option& o, py::handle v) {
  if (o.kind == OptionKind::flag) {
    if (!py::isinstance<py::bool_>(v)) wrong_type(o, "a bool", v);
    values.set_flag(o.name, v.cast<bool>());
  } else if (o.kind == OptionKind::repeated && !py::isinstance<py::str>(v) && py::isinstance<py::sequence>(v)) {
    for (const auto& item : v.cast<py::sequence>()) values.set(o.name, value_text(o, item));
  } else if (o.takes_columns && py::isinstance<py::dict>(v)) {
    values.tables[o.name] = table_of_columns(o.python_name(), v.cast<py::dict>());
    values.set(o.name, o.python_name());
  } else if (o.takes_document && py::isinstance<py::dict>(v)) {
    // NumPy arrays and scalars as JSON lists and numbers (a calibration straight from calibrate()).
    const py::cpp_function plain([](py::handle x) -> py::object {
      if (py::hasattr(x, "tolist")) return x.attr("tolist")();
      throw py::type_error("not a JSON value: " + type_name(x));
    });
    const std::string text =
        py::str(py::module_::import("json").attr("dumps")(v, py::arg("default") = plain)).cast<std::string>();
    values.documents[o.name] = commands::parse_json_file_text(text, o.python_name());
    values.set(o.name, o.python_name());
  } else if (o.takes_positions && !py::isinstance<py::str>(v) && !py::hasattr(v, "__fspath__")) {
    values.program = program_of(v, o.python_name());  // an (N, 3) array of directions
    values.set(o.name, "positions");
  } else {
    values.set(o.name, value_text(o, v));
  }
}

}  // namespace

commands::Values arguments(const commands::CommandTable& table, const py::tuple& args, const py::dict& kwargs) {
  commands::Values values(table);
  std::size_t next = 0;
  const auto positional = std::count_if(table.options.begin(), table.options.end(), [](const Option& o) {
    return o.kind == OptionKind::positional && !o.cli_only;
  });
  if (static_cast<std::ptrdiff_t>(args.size()) > positional)
    throw py::type_error(table.name + "() takes " + std::to_string(positional) + " positional argument" +
                         (positional == 1 ? "" : "s") + " but " + std::to_string(args.size()) +
                         (args.size() == 1 ? " was" : " were") + " given");
  for (const auto& arg : args) {
    while (next < table.options.size() &&
           (table.options[next].kind != OptionKind::positional || table.options[next].cli_only))
      ++next;
    set(values, table.options[next++], arg);
  }
  for (const auto& [key, v] : kwargs) {
    const std::string name = key.cast<std::string>();
    const Option* o = table.find(name);
    if (!o || o->cli_only || o->python_name() != name)
      throw py::type_error(table.name + "() got an unexpected keyword argument '" + name + "'");
    if (v.is_none()) continue;  // None: the option's default
    set(values, *o, v);
  }
  for (const auto& o : table.options)
    if (o.required() && !o.cli_only && !values.given(o.name))
      throw py::type_error(table.name + "() missing required argument '" + o.python_name() + "'");
  commands::check_distinct_outputs(values);
  return values;
}

}  // namespace scalcal::python
