// A calibration in any units, as a user applies it: physical = matrix (raw - offset). Its paper
// form (eq. 2, raw = Delta + (E + dK) Phi I) follows from the matrix: the bias is the offset, the
// scale factor k_i the length of row i of matrix^-1, Phi's rows the sensors' unit axes. Scalar
// calibration sees only the lengths and the cosines between the axes, not a rotation of them all,
// so Phi is taken with its rotation part zero: phi_kj = phi_jk (the paper's gamma_kj = phi_kj +
// phi_jk split evenly, as MeterTpl::from_parameters does), and any matrix is brought to that form.
#pragma once
#include <optional>
#include <vector>

#include "numeric/calibration/meter_model.hpp"

namespace scalcal {

struct FullCorrection {
  Vec3 offset = Vec3::Zero();            // file units
  Mat3 matrix = Mat3::Identity();        // physical per file unit
  Vec3 scale = Vec3::Ones();             // k_i: file units per physical unit
  Vec3 nonorthogonality = Vec3::Zero();  // gamma_xy, gamma_yz, gamma_zx (radians): phi_kj + phi_jk
  Mat3 phi = Mat3::Identity();           // the sensors' unit axes (rows), phi_kj = phi_jk

  Vec3 apply(const Vec3& raw) const { return matrix * (raw - offset); }
};

// The correction of a meter (from the paper's estimate): matrix = gain^-1, offset = bias.
FullCorrection correction_of(const Meter& meter);

// The same correction brought to the paper's convention (the rotation that scalar calibration
// cannot see removed): the returned matrix gives every modulus the given one gives, |C (r - o)|.
// Empty when the axes are degenerate (matrix singular, or two axes nearly parallel).
std::optional<FullCorrection> canonical_correction(const Mat3& matrix, const Vec3& offset);

// The quadrics a start may fit: the general ellipsoid (9 unknowns, falling back to the axis-aligned
// one), the axis-aligned ellipsoid (6: offsets and one gain per axis), the sphere (4: offsets and
// one gain). A model's start must not hold more than the model: axis6's start is axis-aligned,
// bias3's a sphere, or the start would carry what the layout cannot identify.
enum class EllipsoidShape { general, axis_aligned, sphere };

// A closed-form start in any units: the ellipsoid through the positions' mean measurements, as
// physical = matrix (raw - offset) with |physical| = magnitude on it, by linear least squares.
// Empty when the positions determine no ellipsoid of that shape.
std::optional<FullCorrection> fit_ellipsoid(const std::vector<Vec3>& means, double magnitude,
                                            EllipsoidShape shape = EllipsoidShape::general);

}  // namespace scalcal
