// The best way to mount a meter in a jig: the rotation O (rows: the meter's axes in jig coordinates)
// minimising a criterion of the program O n_1, ..., O n_N for the jig's fixed face normals n_j. A
// three-parameter multistart (the default mounting, then seeded uniform rotations) of Nelder-Mead in
// rotation-vector coordinates, which needs no gradient and so serves the nonsmooth E and S as D and A.
#pragma once
#include <cstdint>
#include <functional>

#include <Eigen/Core>

#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct MountingOptions {
  CriterionKind criterion = CriterionKind::D;
  int starts = 64;  // the first is the jig's default mounting (O = I)
  std::uint64_t seed = 1;
  std::function<void(int done, int total)> progress;
};

struct MountingResult {
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  // rows: the meter's axes in jig coordinates
  double value = 0;                                           // the criterion at `orientation`
  double value_default = 0;                                   // at O = I
  int starts = 0;
  int hits = 0;       // starts that ended within kHitTolerance of `value`
  double spread = 0;  // largest relative distance of a hit's value from `value`: the precision reached
};

// The program O n_j.
Program mounted(const Eigen::Matrix3d& orientation, const Program& normals);

// The rotation of `uniform` draws u1, u2, u3 in [0, 1) (Shoemake's uniform rotation).
Eigen::Matrix3d uniform_rotation(double u1, double u2, double u3);

// Throws std::invalid_argument for an empty jig or starts < 1.
MountingResult best_mounting(const Program& normals, const MountingOptions& options);

}  // namespace scalcal
