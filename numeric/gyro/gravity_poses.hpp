// The still poses of a hand-rotation log as the gyro's fit needs them: the accelerometer's static
// intervals (found in its own log), each with gravity's direction from the accelerometer's
// calibration (physical = matrix (raw - offset): the corrected frame the gyro is mapped into) and
// the standard error of that direction from the samples' scatter.
#pragma once
#include <vector>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/gyro/hand_rotations.hpp"

namespace scalcal::gyro {

// Throws InputError (the gyro's file) when the two logs do not have the same time stamps (to 1e-6 s
// or a thousandth of the sample period).
std::vector<GyroPose> gravity_poses(const RawLog& accelerometer, const RawLog& gyro,
                                    const std::vector<StaticInterval>& intervals, const FullCorrection& correction);

}  // namespace scalcal::gyro
