// Hand rotations (IMU-TK's method, Tedaldi, Pretto and Menegatti, ICRA 2014): an accelerometer and a
// gyro moved by hand between still poses. The calibrated accelerometer gives gravity's direction g_k
// in its corrected frame at each pose; the gyro, corrected as Omega = C (w - o) and integrated from
// pose k to pose k+1 (R_k, rotation_integral.hpp), must carry one into the next: R_k^T g_k = g_k+1.
// C (nine entries: scale factors, non-orthogonality and the rotation into the accelerometer's frame)
// and o are fitted to every pair of consecutive poses and, unlike IMU-TK (which takes o from the first
// still period and keeps it), to the gyro's mean output in every pose, which is o (the Earth's rate,
// 7.3e-5 rad/s, is left out). Each group's weights come from its noise (the gyro's angle random walk
// over the motion, the gravity directions' scatter; the rests' scatter), rescaled by the group's own
// residuals (variance components), so the standard errors are the achieved ones, never below the
// predicted. physical = C (raw - o), in the accelerometer's corrected frame.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/gyro/rotation_integral.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal::gyro {

// A still pose seen by both triads.
struct GyroPose {
  int begin = 0, end = 0;        // sample indices (inclusive) in the gyro's log
  Vec3 gravity = Vec3::UnitZ();  // unit: the calibrated accelerometer's mean direction, its corrected frame
  double gravity_std = 0;        // standard error of one component of that direction (rad)
};

struct HandRotationOptions {
  bool bias_from_rests = true;  // the poses' mean gyro outputs observe o (IMU-TK: only its first still period)
  int max_iterations = 100;
  std::optional<Mat3> start_matrix;  // else found from the data (a gain and a signed permutation of the axes)
  std::optional<Vec3> start_offset;  // else the poses' mean gyro output
};

struct PairMisfit {
  int from = 0;        // index of the first pose; the pair is (from, from + 1)
  double angle = 0;    // between the predicted and the measured gravity direction (rad)
  double chord = 0;    // |R^T g_k - g_k+1|, IMU-TK's residual
  double seconds = 0;  // the integration's duration
};

struct GravityMisfit {
  std::vector<PairMisfit> pairs;
  double angle_rms = 0;  // rad
  double chord_rms = 0;
};

struct HandRotationCalibration {
  Mat3 matrix = Mat3::Identity();  // physical per raw unit, into the accelerometer's corrected frame
  Vec3 offset = Vec3::Zero();      // raw units
  // Of (matrix row by row, offset): achieved (the residuals' scale, never below the noise's) and
  // predicted (the noise alone).
  Eigen::Matrix<double, 12, 12> covariance = Eigen::Matrix<double, 12, 12>::Zero();
  Eigen::Matrix<double, 12, 1> standard_error = Eigen::Matrix<double, 12, 1>::Zero();
  Eigen::Matrix<double, 12, 1> predicted_std = Eigen::Matrix<double, 12, 1>::Zero();
  // Achieved over predicted variance of each group (>= 1 after clamping), and its residuals'
  // chi-square against the predicted noise with its degrees of freedom.
  double rotation_scale = 1, rest_scale = 1;
  double rotation_chi_square = 0, rest_chi_square = 0;
  double rotation_dof = 0, rest_dof = 0;
  GravityMisfit misfit;
  int iterations = 0;
  Summary summary;
};

// Throws InputError (gyro.file) when fewer than 4 poses (12 unknowns need 5 pairs or rests), or a pose
// lies outside the log.
HandRotationCalibration calibrate_hand_rotations(const RawLog& gyro, const std::vector<GyroPose>& poses,
                                                 const HandRotationOptions& options = {});

// The misfit of any gyro correction (IMU-TK's, to compare) over the same poses.
GravityMisfit gravity_misfit(const RawLog& gyro, const std::vector<GyroPose>& poses, const Mat3& C, const Vec3& o);

}  // namespace scalcal::gyro
