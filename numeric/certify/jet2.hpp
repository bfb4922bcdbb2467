// A value with its first and second derivatives in the two chart coordinates (u, v) of one
// position: enough to differentiate h(eta(u, v)) twice, in any scalar (MPFR points, MPFI boxes).
#pragma once

namespace scalcal::certify_detail {

template <class T>
struct Jet2 {
  T f, u, v, uu, uv, vv;

  static Jet2 constant(const T& c) { return {c, T(0), T(0), T(0), T(0), T(0)}; }
  friend Jet2 operator+(const Jet2& a, const Jet2& b) {
    return {a.f + b.f, a.u + b.u, a.v + b.v, a.uu + b.uu, a.uv + b.uv, a.vv + b.vv};
  }
  friend Jet2 operator*(const Jet2& a, const Jet2& b) {
    return {a.f * b.f,
            a.u * b.f + a.f * b.u,
            a.v * b.f + a.f * b.v,
            a.uu * b.f + T(2) * a.u * b.u + a.f * b.uu,
            a.uv * b.f + a.u * b.v + a.v * b.u + a.f * b.uv,
            a.vv * b.f + T(2) * a.v * b.v + a.f * b.vv};
  }
  // g(a) from g, g', g'' at a.f (the chain rule to second order).
  Jet2 compose(const T& g, const T& g1, const T& g2) const {
    return {g, g1 * u, g1 * v, g1 * uu + g2 * u * u, g1 * uv + g2 * u * v, g1 * vv + g2 * v * v};
  }
};

}  // namespace scalcal::certify_detail
