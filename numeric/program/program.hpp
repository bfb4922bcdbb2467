// A calibration program: plain data, the N measurement positions (unit vectors eta in the
// meter's frame), with named constructors for the classic programs of the paper's Figs. 1-4.
// Exact constructions use the scalar's own sqrt/cos so they stay exact to 50+ digits.
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "numeric/model/paper9.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {

// pi in the scalar's own precision. In double, 4 atan(1) is exactly the double nearest pi (a
// power-of-two multiple of the correctly rounded atan(1)); a multiprecision atan is good to its
// precision. Not Boost.Math's constant: its header alone pulled 967 headers into every unit that
// names a program (about 3 s of each compile).
template <class Scalar>
Scalar scalar_pi() {
  using std::atan;
  return Scalar(4) * atan(Scalar(1));
}

template <class Scalar>
struct ProgramTpl {
  PositionsT<Scalar> positions;

  int size() const { return static_cast<int>(positions.size()); }

  template <class T>
  ProgramTpl<T> cast() const {
    ProgramTpl<T> out;
    out.positions.reserve(positions.size());
    for (const auto& p : positions) out.positions.push_back(p.template cast<T>());
    return out;
  }

  ProgramTpl& append(const ProgramTpl& other) {
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    return *this;
  }

  // eta = (cos a2 cos a1, cos a2 sin a1, sin a2): a1 azimuth, a2 elevation (Tables 1-3).
  static Vec3T<Scalar> from_angles_deg(const Scalar& a1_deg, const Scalar& a2_deg) {
    using std::cos;
    using std::sin;
    const Scalar deg = scalar_pi<Scalar>() / Scalar(180);
    const Scalar a1 = a1_deg * deg, a2 = a2_deg * deg;
    return Vec3T<Scalar>(cos(a2) * cos(a1), cos(a2) * sin(a1), sin(a2));
  }

  // Uniform-projection orbits of the octahedral group (Fig. 4): the 6 axis positions
  // (projection 1), the 12 edge positions (sqrt(2)/2 on two axes), the 8 diagonal positions
  // (sqrt(3)/3 on all three), each repeated by its multiplicity.
  static ProgramTpl octahedral(int axes, int edges, int diagonals) {
    if (axes < 0 || edges < 0 || diagonals < 0)
      throw std::invalid_argument("octahedral: multiplicities must be non-negative");
    using std::sqrt;
    ProgramTpl p;
    const Scalar one(1), zero(0);
    const Scalar e = sqrt(Scalar(2)) / Scalar(2);
    const Scalar d = sqrt(Scalar(3)) / Scalar(3);
    for (int m = 0; m < axes; ++m)
      for (int axis = 0; axis < 3; ++axis)
        for (int s : {1, -1}) {
          Vec3T<Scalar> v(zero, zero, zero);
          v(axis) = Scalar(s) * one;
          p.positions.push_back(v);
        }
    for (int m = 0; m < edges; ++m)
      for (int axis = 0; axis < 3; ++axis)  // the edge pair (axis, axis+1)
        for (int s1 : {1, -1})
          for (int s2 : {1, -1}) {
            Vec3T<Scalar> v(zero, zero, zero);
            v(axis) = Scalar(s1) * e;
            v((axis + 1) % 3) = Scalar(s2) * e;
            p.positions.push_back(v);
          }
    for (int m = 0; m < diagonals; ++m)
      for (int s1 : {1, -1})
        for (int s2 : {1, -1})
          for (int s3 : {1, -1}) p.positions.push_back(Vec3T<Scalar>(Scalar(s1) * d, Scalar(s2) * d, Scalar(s3) * d));
    return p;
  }

  // Fig. 1, ref. [14]: each axis along and against the vector, and four positions at 45 degrees
  // for each pair of axes (the union of the axis and edge orbits).
  static ProgramTpl classic18() { return octahedral(1, 1, 0); }

  // Fig. 2, ref. [12]: k positions equally spaced while rotating about each axis in turn
  // (3k positions). Ring about z: (cos t, sin t, 0); about x: (0, cos t, sin t); about y:
  // (sin t, 0, cos t), with t = phase + 2 pi j / k. k = 6, phase 0 is the 18-position program.
  static ProgramTpl rotation(int k, const Scalar& phase_deg = Scalar(0)) {
    if (k < 3) throw std::invalid_argument("rotation: k must be at least 3");
    using std::cos;
    using std::sin;
    ProgramTpl p;
    const Scalar zero(0);
    const Scalar deg = scalar_pi<Scalar>() / Scalar(180);
    const Scalar two_pi = Scalar(2) * scalar_pi<Scalar>();
    for (int axis = 0; axis < 3; ++axis) {
      const int a = (axis + 2) % 3;  // rotation about z first: the ring lies in the x-y plane
      for (int j = 0; j < k; ++j) {
        const Scalar t = phase_deg * deg + two_pi * Scalar(j) / Scalar(k);
        Vec3T<Scalar> v(zero, zero, zero);
        v((a + 1) % 3) = cos(t);
        v((a + 2) % 3) = sin(t);
        p.positions.push_back(v);
      }
    }
    return p;
  }

  // Refs. [8, 14]: the six axis positions plus three positions projecting the vector on two
  // axes, one per pair of axes: (1,1,0)/sqrt2, (0,1,1)/sqrt2, (1,0,1)/sqrt2. This is the
  // 18-position program with nine positions removed, as the paper describes [14]'s nine. All 64
  // choices of one edge position per pair give the same N^9 det K = 3^18 (checked by enumeration).
  static ProgramTpl nine_two_axes() {
    using std::sqrt;
    ProgramTpl p = octahedral(1, 0, 0);
    const Scalar e = sqrt(Scalar(2)) / Scalar(2), zero(0);
    p.positions.push_back(Vec3T<Scalar>(e, e, zero));
    p.positions.push_back(Vec3T<Scalar>(zero, e, e));
    p.positions.push_back(Vec3T<Scalar>(e, zero, e));
    return p;
  }

  // Ref. [13]: the six axis positions plus three positions projecting the vector equally on
  // all three axes (sqrt(3)/3). The three diagonals (1,1,1), (-1,1,1), (1,-1,1) over sqrt3: of the
  // 56 choices of three diagonals, the 24 holding an antipodal pair are rank-deficient and the
  // other 32 all give N^9 det K = 275810094 (checked by enumeration); this is one of those 32.
  static ProgramTpl nine_three_axes() {
    using std::sqrt;
    ProgramTpl p = octahedral(1, 0, 0);
    const Scalar d = sqrt(Scalar(3)) / Scalar(3);
    p.positions.push_back(Vec3T<Scalar>(d, d, d));
    p.positions.push_back(Vec3T<Scalar>(-d, d, d));
    p.positions.push_back(Vec3T<Scalar>(d, -d, d));
    return p;
  }

  // Dodecahedral jig (12 faces): positions are the face normals of a regular dodecahedron,
  // i.e. the icosahedron's vertices (0, +-1, +-phi) and cyclic permutations, normalised.
  // Orientation: three two-fold axes of the jig along the meter's axes.
  static ProgramTpl dodecahedral() {
    using std::sqrt;
    ProgramTpl p;
    const Scalar phi = (Scalar(1) + sqrt(Scalar(5))) / Scalar(2);
    const Scalar norm = sqrt(Scalar(1) + phi * phi);
    for (int c = 0; c < 3; ++c)
      for (int s1 : {1, -1})
        for (int s2 : {1, -1}) {
          Vec3T<Scalar> v;
          v(c) = Scalar(0);
          v((c + 1) % 3) = Scalar(s1) / norm;
          v((c + 2) % 3) = Scalar(s2) * phi / norm;
          p.positions.push_back(v);
        }
    return p;
  }

  // Icosahedral jig (20 faces): positions are the face normals of a regular icosahedron, i.e.
  // the dodecahedron's vertices (+-1, +-1, +-1) and (0, +-1/phi, +-phi) cyclic, over sqrt3.
  // Orientation: three two-fold axes of the jig along the meter's axes.
  static ProgramTpl icosahedral() {
    using std::sqrt;
    ProgramTpl p;
    const Scalar phi = (Scalar(1) + sqrt(Scalar(5))) / Scalar(2);
    const Scalar norm = sqrt(Scalar(3));
    for (int s1 : {1, -1})
      for (int s2 : {1, -1})
        for (int s3 : {1, -1}) p.positions.push_back(Vec3T<Scalar>(Scalar(s1), Scalar(s2), Scalar(s3)) / norm);
    for (int c = 0; c < 3; ++c)
      for (int s1 : {1, -1})
        for (int s2 : {1, -1}) {
          Vec3T<Scalar> v;
          v(c) = Scalar(0);
          v((c + 1) % 3) = Scalar(s1) / (phi * norm);
          v((c + 2) % 3) = Scalar(s2) * phi / norm;
          p.positions.push_back(v);
        }
    return p;
  }

  // N positions drawn independently and uniformly on the sphere; the same seed gives the same
  // program on every machine (the generator is specified to the bit, see random_sphere.hpp).
  static ProgramTpl random(int n, std::uint64_t seed) {
    if (n < 1) throw std::invalid_argument("random: N must be positive");
    ProgramTpl p;
    SphereSampler sampler(seed);
    for (int i = 0; i < n; ++i) p.positions.push_back(sampler().template cast<Scalar>());
    return p;
  }
};

using Program = ProgramTpl<double>;

}  // namespace scalcal
