// A tumbling log: a meter whose field survives motion (a magnetometer) turned continuously, as
// MATLAB's magcal, MotionCal, PX4 and ArduPilot calibrate it: every usable sample is a position of
// one sample. What this needs beyond the still-pose path: disturbed stretches (a magnet passing, a
// spike) found from the fit's own residuals and left out; standard errors that allow for residuals
// correlated in time (neighbouring samples share the motion's and the disturbances' errors), by a
// Newey-West covariance; and what the tumbling covered of the sphere.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {

// A sample whose residual is beyond this many robust scales (about 5 sigma) is disturbed; its
// stretch grows over the neighbours beyond half that.
inline constexpr double kDisturbedScales = 5;

struct DisturbedStretch {
  int begin = 0, end = 0;             // sample indices, inclusive
  double start = 0, stop = 0;         // seconds
  int first_line = 0, last_line = 0;  // in the log's file
  double worst = 0;                   // the largest |residual| in it, relative to the modulus
  int samples() const { return end - begin + 1; }
};

// One position per sample with use[i] set, in time order; sample_index[k] is position k's sample.
std::vector<PositionSamples> sample_positions(const RawLog& log, const std::vector<char>& use,
                                              std::vector<int>& sample_index);

// The stretches of disturbed samples: residual[k] belongs to sample sample_index[k]; runs closer
// than `gap` samples merge.
std::vector<DisturbedStretch> disturbed_stretches(const RawLog& log, const std::vector<int>& sample_index,
                                                  const std::vector<double>& residual, int gap);

// The model's rows at unit directions.
std::vector<Eigen::VectorXd> model_rows(ModelKind model, const std::vector<Vec3>& directions);

// The covariance of the least-squares parameters with residuals correlated in time: (H^T H)^-1 S
// (H^T H)^-1, S the Bartlett-weighted sum of h_t r_t r_s h_s^T over |t - s| <= lag (Newey and West
// 1987), times N / (N - P). Rows and residuals in time order.
Eigen::MatrixXd newey_west_covariance(const std::vector<Eigen::VectorXd>& rows, const std::vector<double>& residual,
                                      int lag);

// A scalar misfit that depends on the direction (the model's own error, a soft-iron term it lacks)
// is shared by samples until the meter has turned away: the residuals of a hand's tumbling are
// correlated over seconds, not over the noise's few samples. This is the smallest lag (in samples)
// at which the median angle between directions that far apart reaches kDecorrelationAngle,
// searched by doubling then bisection up to a quarter of the log (that quarter when never reached).
inline constexpr double kDecorrelationAngle = M_PI / 3;
int decorrelation_lag(const std::vector<Vec3>& directions);

// What a set of directions covers: the share of 100 equal-area cells of the sphere holding one, and
// the largest cap holding none (its angular radius in degrees, searched on 2000 centres, and where).
struct Coverage {
  double covered_share = 0;
  double largest_gap_deg = 0;
  Vec3 gap_centre = Vec3::UnitZ();
};
Coverage sphere_coverage(const std::vector<Vec3>& directions);

// n points spread evenly over the sphere (the Fibonacci lattice).
std::vector<Vec3> fibonacci_sphere(int n);

}  // namespace scalcal
