// Local coordinates (u, v) for each position of a program: eta = w / |w| with w = e + u t1 + v t2,
// where e is the computed position and t1, t2 span its tangent plane. Exact in any scalar, smooth
// near (0, 0), and free of the poles' singularity that spherical angles have.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "numeric/certify/jet2.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

struct SphereChart {
  std::vector<Eigen::Vector3d> e, t1, t2;

  // gauge_pair: for a rotation-invariant criterion, t1 of position `second` is chosen along
  // e[first] x e[second], so fixing u of `second` (with u, v of `first`) removes the rotations.
  static SphereChart of(const Program& p, int first = -1, int second = -1) {
    SphereChart c;
    for (int i = 0; i < p.size(); ++i) {
      const Eigen::Vector3d e = p.positions[i].normalized();
      Eigen::Vector3d t = (i == second) ? p.positions[first].cross(e) : e.unitOrthogonal();
      t.normalize();
      c.e.push_back(e);
      c.t1.push_back(t);
      c.t2.push_back(e.cross(t).normalized());
    }
    return c;
  }

  // eta(u, v) of position i with its derivatives.
  template <class T>
  std::array<Jet2<T>, 3> position(int i, const T& u, const T& v) const {
    std::array<Jet2<T>, 3> w;
    for (int k = 0; k < 3; ++k)
      w[k] = Jet2<T>{T(e[i](k)) + u * T(t1[i](k)) + v * T(t2[i](k)), T(t1[i](k)), T(t2[i](k)), T(0), T(0), T(0)};
    const Jet2<T> s = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    using std::sqrt;
    const T r = sqrt(s.f);
    const T g = T(1) / r, g1 = T(-1) / (T(2) * r * s.f), g2 = T(3) / (T(4) * r * s.f * s.f);
    const Jet2<T> inv = s.compose(g, g1, g2);
    return {w[0] * inv, w[1] * inv, w[2] * inv};
  }

  // The rounded positions at chart coordinates x = (u0, v0, u1, v1, ...).
  Program program_at(const Eigen::VectorXd& x) const {
    Program p;
    for (std::size_t i = 0; i < e.size(); ++i)
      p.positions.push_back((e[i] + x(2 * i) * t1[i] + x(2 * i + 1) * t2[i]).normalized());
    return p;
  }
};

// h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx) of the paper's model, as jets.
template <class T>
std::array<Jet2<T>, 9> paper9_row(const std::array<Jet2<T>, 3>& e) {
  return {e[0], e[1], e[2], e[0] * e[0], e[1] * e[1], e[2] * e[2], e[0] * e[1], e[1] * e[2], e[2] * e[0]};
}

}  // namespace scalcal::certify_detail
