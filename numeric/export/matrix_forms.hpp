// The forms a target stores a 3x3 correction in, each from scalcal's matrix C: a symmetric matrix
// times a rotation (PX4's and ArduPilot's soft iron), a rotation times a lower-triangular matrix
// (Kalibr's and OpenVINS's scale-misalignment), the diagonal alone (PX4's and ArduPilot's
// accelerometer), and how much of a corrected vector each form loses.
#pragma once
#include <optional>

#include "numeric/model/model.hpp"

namespace scalcal {

// S of C = Q S, Q a rotation and S symmetric positive definite: |S v| = |C v| for every v.
Mat3 symmetric_factor(const Mat3& C);

// C = Q L with Q a proper rotation and L lower triangular with a positive diagonal; empty when
// det C <= 0 (left-handed axes: no rotation and positive triangle make it).
struct RotationTriangle {
  Mat3 rotation = Mat3::Identity();
  Mat3 lower = Mat3::Identity();
};
std::optional<RotationTriangle> rotation_times_lower(const Mat3& C);

// The angle of a rotation matrix (radians).
double rotation_angle(const Mat3& R);

// The largest |(C - D) v| / |C v| over directions v, for D what the target keeps of C.
double dropped_share(const Mat3& C, const Mat3& kept);

// The angle of the rotation C holds beyond the paper's convention (the misalignment's rotation part
// zero, full_correction.hpp), which scalar calibration never determines: 0 for every matrix
// `calibrate` writes, the angle of a mounting rotation composed into a matrix by hand or by another
// tool. NaN for a degenerate matrix.
double rotation_beyond_convention(const Mat3& C);

}  // namespace scalcal
