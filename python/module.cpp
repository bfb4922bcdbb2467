// The extension `scalcal._scalcal`: the option tables of every command and one entry point that runs
// a command from Python arguments (python/scalcal/__init__.py turns each table into a function with
// its signature and docstring). Calls from several threads take turns (one lock); the GIL is released
// while scalcal computes in a thread of its own, and the caller's thread checks for Ctrl-C meanwhile
// (KeyboardInterrupt stops the command within a unit of work).
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "commands/core/build_features.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/research/sweep.hpp"
#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/io/blas_kernel.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/interrupt.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/io/resource_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/from_numpy.hpp"
#include "python/library_lock.hpp"
#include "python/stream.hpp"
#include "python/to_python.hpp"

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

// Interval at which a running command lets Python see Ctrl-C.
constexpr auto kSignalPoll = std::chrono::milliseconds(50);

// b.run(values) in a thread of its own while this one, every 50 ms, takes the GIL and lets Python
// run its signal handlers: Ctrl-C raises KeyboardInterrupt here, the library is asked to stop
// (numeric/io/interrupt.hpp; its loops look between units of work) and the call returns once it has.
// Without a thread to spare (a process limit) the command runs here and Ctrl-C waits for its end.
Output run_interruptibly(const Binding& b, const commands::Values& values) {
  const commands::Progress stop_point = [](std::string_view, int, int) { check_interrupt(); };
  std::optional<Output> out;
  std::exception_ptr error;
  std::mutex m;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  {
    py::gil_scoped_release free;
    const auto work = [&] {
      try {
        out = b.run(values, stop_point);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> g(m);
      done = true;
      finished.notify_all();
    };
    std::thread worker;
    try {
      worker = std::thread(work);
    } catch (const std::system_error&) {
      work();
    }
    std::unique_lock<std::mutex> wait(m);
    while (!done) {
      if (finished.wait_for(wait, kSignalPoll, [&] { return done; })) break;
      wait.unlock();
      {
        py::gil_scoped_acquire hold;
        // The error indicator PyErr_CheckSignals sets stays on this thread until it is raised below.
        if (!interrupted && PyErr_CheckSignals() != 0) {
          interrupted = true;
          interrupt_request().store(true);
        }
      }
      wait.lock();
    }
    wait.unlock();
    if (worker.joinable()) worker.join();
    interrupt_request().store(false);
  }
  if (interrupted) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*out);
}

// run(name, args, kwargs) -> (result, [(subject, message)], status)
py::tuple run(const std::string& name, const py::tuple& args, const py::dict& kwargs) {
  const Binding& b = binding(name);
  std::optional<Output> out;
  {
    const LibraryLock lock;  // the arguments too: a program name may be a family's (GiNaC)
    const commands::Values values = arguments(*b.table, args, kwargs);
    out = run_interruptibly(b, values);
  }
  py::list warnings;
  for (const auto& w : out->warnings) warnings.append(py::make_tuple(w.subject, w.message));
  return py::make_tuple(to_python(out->json), warnings, out->status);
}

// sweep_tasks(args, kwargs) -> [(criterion, N), ...]: the tasks of sweep(*args, **kwargs) in their order,
// for sweep(map=...) to run one shard per task.
py::list sweep_tasks(const py::tuple& args, const py::dict& kwargs) {
  const LibraryLock lock;
  const commands::Sweep sweep(commands::sweep_request(arguments(commands::sweep_table(), args, kwargs)));
  py::list out;
  for (const auto& t : sweep.tasks()) out.append(py::make_tuple(std::string(criterion_name(t.criterion)), t.positions));
  return out;
}

// build_info() -> {"version", "ginac", "lacking": {command: the line the CLI gives for it}}.
py::dict build_info() {
  py::dict lacking;
  for (const auto& c : commands::lacking_commands()) lacking[py::str(c.name)] = commands::lacking_message(c);
  py::dict out;
  out["version"] = SCALCAL_VERSION;
  out["ginac"] = commands::with_ginac();
  out["lacking"] = lacking;
  return out;
}

py::object program(const std::string& name) {
  const LibraryLock lock;
  return to_python(commands::program_json(resolve_program(name)));
}

}  // namespace
}  // namespace scalcal::python

PYBIND11_MODULE(_scalcal, m) {
  namespace sp = scalcal::python;
  m.doc() = "scalcal's compiled core: option tables and one runner (use the package `scalcal`)";
  m.attr("__version__") = SCALCAL_VERSION;
  m.def("blas_kernel", &scalcal::blas_kernel, "the OpenBLAS kernel in use (\"\" for another BLAS)");
  scalcal::set_option_style(scalcal::OptionStyle::python);  // messages say threshold_factor=, not --threshold-factor
  scalcal::commands::register_family_programs();            // the families' program names, as the CLI has them
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
  m.def("program", &sp::program, py::arg("name"));
  m.def("build_info", &sp::build_info);
  m.def("sweep_tasks", &sp::sweep_tasks, py::arg("args"), py::arg("kwargs"));
  sp::bind_stream(m);
}
