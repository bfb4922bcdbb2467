// The double instantiation of the estimator lives here, once, so that every user of the header
// does not recompile it.
#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

template CalibrationResultTpl<double> calibrate(const std::vector<PositionSamplesTpl<double>>&,
                                                const CalibrationOptionsTpl<double>&);

}  // namespace scalcal
