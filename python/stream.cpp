// scalcal.PoseStream's compiled half (stream.hpp): chunks of NumPy rows into a CalibrationStream, its
// poses out, and the fit on request through calibrate's own request and code.
#include "python/stream.hpp"

#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibrate_json.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/calibration/calibration_stream.hpp"
#include "python/arguments.hpp"
#include "python/library_lock.hpp"
#include "python/to_python.hpp"

namespace scalcal::python {
namespace {

namespace py = pybind11;
using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

StaticIntervalOptions options_of(std::optional<double> still, std::optional<double> window,
                                 std::optional<double> threshold_factor, std::optional<double> min_interval) {
  StaticIntervalOptions o;
  const auto positive = [](const char* name, std::optional<double> v, double& to) {
    if (!v) return;
    if (!(*v > 0) || !std::isfinite(*v))
      throw UsageError(std::string("PoseStream: ") + name + " must be a positive number");
    to = *v;
  };
  positive("still", still, o.still_seconds);
  positive("window", window, o.window_seconds);
  positive("threshold_factor", threshold_factor, o.threshold_factor);
  positive("min_interval", min_interval, o.min_seconds);
  return o;
}

class PoseStream {
 public:
  PoseStream(std::string name, std::optional<double> still, std::optional<double> window,
             std::optional<double> threshold_factor, std::optional<double> min_interval)
      : name_(std::move(name)),
        options_(options_of(still, window, threshold_factor, min_interval)),
        given_(still || window || threshold_factor || min_interval),
        stream_(name_, options_, !given_) {}

  // Rows t (n,) in seconds and samples (n, 3) in the meter's raw units; last: the log ends here.
  void add(const Rows& t, const Rows& samples, bool last) {
    if (t.ndim() != 1 || samples.ndim() != 2 || samples.shape(1) != 3 || samples.shape(0) != t.shape(0))
      throw UsageError("PoseStream.add: t must be a 1-D array and samples an (n, 3) array of the same n rows, got " +
                       std::to_string(t.ndim()) + "-D and " + std::to_string(samples.ndim()) + "-D");
    RawLog chunk;
    chunk.file = name_;
    const auto n = t.shape(0);
    const int first = stream_.log().size();
    for (py::ssize_t i = 0; i < n; ++i) {
      chunk.t.push_back(t.at(i));
      chunk.samples.emplace_back(samples.at(i, 0), samples.at(i, 1), samples.at(i, 2));
      chunk.lines.push_back(first + static_cast<int>(i) + 1);  // the row's number in the stream, from 1
    }
    const LibraryLock lock;
    stream_.add(chunk, last);
  }

  // The poses settled so far: begin/end rows (from 0), start/stop seconds, samples, mean, variance.
  py::list poses() const {
    const LibraryLock lock;
    py::list out;
    const IntervalDetection d = stream_.detection();
    const std::vector<PoseSums> sums = stream_.pose_sums();
    for (std::size_t k = 0; k < sums.size(); ++k) {
      py::dict p;
      p["begin"] = sums[k].begin;
      p["end"] = sums[k].end;
      p["start"] = d.intervals[k].start;
      p["stop"] = d.intervals[k].stop;
      p["samples"] = sums[k].samples;
      p["mean"] = py::make_tuple(sums[k].mean(0), sums[k].mean(1), sums[k].mean(2));
      p["variance"] = py::make_tuple(sums[k].variance(0), sums[k].variance(1), sums[k].variance(2));
      out.append(p);
    }
    return out;
  }

  // The stream's state: rows taken, chunks, whether it ended, the detection's window, floor, threshold.
  py::dict state() const {
    const LibraryLock lock;
    py::dict s;
    s["rows"] = stream_.log().size();
    s["chunks"] = stream_.chunks();
    const IntervalDetection d = stream_.detection();
    s["poses"] = d.intervals.size();
    s["window"] = d.window;
    s["noise_floor"] = d.still_variance > 0 ? py::object(py::float_(d.still_variance)) : py::none();
    s["static_threshold"] = d.threshold > 0 ? py::object(py::float_(d.threshold)) : py::none();
    return s;
  }

  // calibrate's request from Python keywords (the stream's own name as its file), its fit of the
  // poses settled so far: (the calibration file's object, warnings, status).
  py::tuple calibrate(const py::dict& kwargs) const {
    for (const char* own :
         {"measurements", "rate", "format", "still", "window", "threshold_factor", "min_interval", "chunk"})
      if (kwargs.contains(own))
        throw UsageError(std::string("PoseStream.calibrate: ") + own +
                         " belongs to the stream (its rows and detection are given already)");
    py::dict all(kwargs);
    all["measurements"] = name_;
    std::optional<commands::CalibrateResult> r;
    {
      const LibraryLock lock;
      commands::CalibrateRequest q =
          commands::calibrate_request(arguments(commands::calibrate_table(), py::tuple(), all));
      commands::check_calibrate_request(q);
      q.intervals = options_;
      q.intervals_given = given_;
      r = commands::calibrate(q, commands::calibration_input(stream_, q));
    }
    py::list warnings;
    for (const auto& w : r->warnings) warnings.append(py::make_tuple(w.subject, w.message));
    return py::make_tuple(to_python(commands::calibration_file_json(*r)), warnings, r->status());
  }

 private:
  std::string name_;
  StaticIntervalOptions options_;
  bool given_;
  CalibrationStream stream_;
};

}  // namespace

void bind_stream(py::module_& m) {
  py::class_<PoseStream>(m, "PoseStream")
      .def(py::init<std::string, std::optional<double>, std::optional<double>, std::optional<double>,
                    std::optional<double>>(),
           py::arg("name"), py::arg("still"), py::arg("window"), py::arg("threshold_factor"), py::arg("min_interval"))
      .def("add", &PoseStream::add, py::arg("t"), py::arg("samples"), py::arg("last"))
      .def("poses", &PoseStream::poses)
      .def("state", &PoseStream::state)
      .def("calibrate", &PoseStream::calibrate, py::arg("kwargs"));
}

}  // namespace scalcal::python
