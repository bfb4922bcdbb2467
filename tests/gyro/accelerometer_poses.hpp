// The accelerometer of a hand-rotation log calibrated as calibrate does it (its static intervals,
// each a position counted once, any units), and gravity's poses for the gyro: shared by the gyro's
// tests that start from two logs.
#pragma once
#include <string>
#include <vector>

#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/gyro/gravity_poses.hpp"

namespace scalcal::gyro::testing {

struct AccelerometerPoses {
  IntervalDetection detection;
  AnyUnitsCalibration accelerometer;
  std::vector<GyroPose> poses;
};

inline AccelerometerPoses accelerometer_poses(const RawLog& acc, const RawLog& gyro, double g,
                                              const char* model = "paper9") {
  AccelerometerPoses out;
  out.detection = detect_static_intervals(acc);
  std::vector<PositionSamples> data;
  for (const auto& iv : out.detection.intervals) {
    PositionSamples p;
    for (int i = iv.begin; i <= iv.end; ++i) p.samples.push_back(acc.samples[static_cast<std::size_t>(i)]);
    data.push_back(p);
  }
  AnyUnitsOptions o;
  o.magnitude = g;
  o.weight_by_samples = false;
  o.model = *parse_model(model);
  out.accelerometer = calibrate_any_units(acc.file, data, o);
  out.poses = gravity_poses(acc, gyro, out.detection.intervals, out.accelerometer.correction);
  return out;
}

}  // namespace scalcal::gyro::testing
