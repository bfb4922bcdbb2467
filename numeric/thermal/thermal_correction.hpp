// A fitted thermal calibration as firmware applies it: at a temperature T (clamped to the fitted range, as
// PX4 and ArduPilot hold their polynomials at the ends), physical = C(T) (raw - o(T)) in the log's units,
// and the offset o(T) = |I| (b_0 + sum_j b_j tau^j) as a polynomial in (T - reference) per degC^j, the
// form the autopilots store (PX4 about TC_A0_TREF, ArduPilot about 35 degC).
#pragma once
#include <Eigen/Core>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/thermal/temperature_range.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal {

struct ThermalCorrection {
  ThermalModel model;
  TemperatureRange range;        // fitted over; outside it the correction is held at the ends
  double magnitude = 1;          // |I| in the log's units (raw and physical units are the log's)
  Eigen::VectorXd coefficients;  // model.parameter_names() order, coefficients of tau^j

  double clamped(double celsius) const;
  // The correction at a temperature (clamped): matrix and offset of the base meter at tau(T).
  FullCorrection at(double celsius) const;
  // Row i, column j: the offset's coefficient of (T - reference)^j per degC^j, j = 0..degree, in the
  // log's units: o(T) exactly, for any reference (a binomial re-expansion of the tau polynomial).
  Eigen::Matrix<double, 3, Eigen::Dynamic> offset_polynomial(double reference) const;
};

}  // namespace scalcal
