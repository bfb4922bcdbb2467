// The extension `scalcal._scalcal`: the option tables of every command and one entry point that runs
// a command from Python arguments (python/scalcal/__init__.py turns each table into a function with
// its signature and docstring). The GIL is released while scalcal computes; between units of work the
// command's progress callback takes it back to check for Ctrl-C (KeyboardInterrupt stops the command).
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "commands/usage_error.hpp"
#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/resource_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/from_numpy.hpp"
#include "python/to_python.hpp"
#include "symbolic/family.hpp"

namespace py = pybind11;

namespace scalcal::python {
namespace {

const char* kind_name(commands::OptionKind k) {
  switch (k) {
    case commands::OptionKind::positional:
      return "positional";
    case commands::OptionKind::integer:
      return "integer";
    case commands::OptionKind::number:
      return "number";
    case commands::OptionKind::text:
      return "text";
    case commands::OptionKind::choice:
      return "choice";
    case commands::OptionKind::flag:
      return "flag";
    case commands::OptionKind::repeated:
      return "repeated";
  }
  return "text";
}

// The tables as plain dicts, for the Python layer's signatures, docstrings and type stubs.
py::list tables() {
  py::list out;
  for (const auto& b : bindings()) {
    const auto& t = *b.table;
    py::list options;
    for (const auto& o : t.options) {
      if (o.cli_only) continue;
      py::dict d;
      d["option"] = o.name;
      d["name"] = o.python_name();
      d["kind"] = kind_name(o.kind);
      d["help"] = o.help();
      d["required"] = o.required();
      d["default"] = o.fallback == commands::kRequired ? std::string() : o.fallback;
      d["default_text"] = o.fallback_text;  // a default stated in words ("0 = all cores")
      d["choices"] = o.choices;
      d["positions"] = o.takes_positions;
      d["columns"] = o.takes_columns;
      d["document"] = o.takes_document;
      options.append(d);
    }
    py::dict d;
    d["name"] = t.name;
    d["summary"] = t.summary;
    d["usage"] = "scalcal " + t.usage();
    d["options"] = options;
    out.append(d);
  }
  return out;
}

// run(name, args, kwargs) -> (result, [(subject, message)], status)
py::tuple run(const std::string& name, const py::tuple& args, const py::dict& kwargs) {
  const Binding& b = binding(name);
  const commands::Values values = arguments(*b.table, args, kwargs);
  const commands::Progress check_signals = [](std::string_view, int, int) {
    py::gil_scoped_acquire hold;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  std::optional<Output> out;
  {
    py::gil_scoped_release free;
    out = b.run(values, check_signals);
  }
  py::list warnings;
  for (const auto& w : out->warnings) warnings.append(py::make_tuple(w.subject, w.message));
  return py::make_tuple(to_python(out->json), warnings, out->status);
}

}  // namespace
}  // namespace scalcal::python

PYBIND11_MODULE(_scalcal, m) {
  namespace sp = scalcal::python;
  m.doc() = "scalcal's compiled core: option tables and one runner (use the package `scalcal`)";
  m.attr("__version__") = SCALCAL_VERSION;
  scalcal::symbolic::register_family_programs();  // the families' program names, as the CLI has them
  static py::exception<scalcal::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<scalcal::UsageError> usage_error(m, "UsageError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const scalcal::InputError& e) {
      input_error(e.what());
    } catch (const scalcal::UsageError& e) {
      usage_error(e.what());
    } catch (const scalcal::ResourceError& e) {
      PyErr_SetString(PyExc_OSError, e.what());  // the machine's limits, as Python reports them
    }
  });
  m.def("tables", &sp::tables);
  m.def("run", &sp::run, py::arg("name"), py::arg("args"), py::arg("kwargs"));
  m.def(
      "program",
      [](const std::string& name) {
        return sp::to_python(scalcal::commands::program_json(scalcal::resolve_program(name)));
      },
      py::arg("name"));
}
