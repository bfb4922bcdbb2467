// scalcal.PoseStream's compiled half: numeric/calibration/calibration_stream.hpp for Python.
#pragma once
#include <pybind11/pybind11.h>

namespace scalcal::python {

// _scalcal.PoseStream(name, still, window, threshold_factor, min_interval): add(t, samples, last),
// poses(), detection(), calibrate(kwargs) -> (calibration file's object, [(subject, message)], status).
void bind_stream(pybind11::module_& m);

}  // namespace scalcal::python
