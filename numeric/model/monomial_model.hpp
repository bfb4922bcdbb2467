// A model whose design row is a list of monomials x^a y^b z^c of the position: a new model of this
// kind is its table of exponents, names and groups (see axis6.hpp); the row, its Jacobian and its
// curvature follow from the table.
#pragma once
#include <array>

#include "numeric/model/model.hpp"

namespace scalcal {

using Exponents = std::array<int, 3>;

namespace detail {
template <class Scalar>
Scalar power(const Scalar& x, int k) {
  Scalar out(1);
  for (int i = 0; i < k; ++i) out *= x;
  return out;
}
// d^m/dx_j^m of the monomial with exponents e, as a coefficient times a monomial.
template <class Scalar>
Scalar monomial(const Vec3T<Scalar>& x, Exponents e) {
  return power(x(0), e[0]) * power(x(1), e[1]) * power(x(2), e[2]);
}
}  // namespace detail

// Derived gives kParameters, name, parameter_names, parameter_groups and `exponents`. The return
// types are deduced so that nothing of Derived is needed before it is complete.
template <class Derived>
struct MonomialModel {
  template <class Scalar>
  static auto row(const Vec3T<Scalar>& x) {
    RowT<Derived, Scalar> h;
    for (int r = 0; r < Derived::kParameters; ++r)
      h(r) = detail::monomial(x, Derived::exponents[static_cast<std::size_t>(r)]);
    return h;
  }

  template <class Scalar>
  static auto jacobian(const Vec3T<Scalar>& x) {
    JacobianT<Derived, Scalar> J;
    for (int r = 0; r < Derived::kParameters; ++r)
      for (int j = 0; j < 3; ++j) {
        Exponents e = Derived::exponents[static_cast<std::size_t>(r)];
        const int k = e[static_cast<std::size_t>(j)];
        if (k == 0) {
          J(r, j) = Scalar(0);
          continue;
        }
        e[static_cast<std::size_t>(j)] = k - 1;
        J(r, j) = Scalar(k) * detail::monomial(x, e);
      }
    return J;
  }

  // sum_r w_r d^2 h_r / dx^2 at x (only monomials of degree >= 2 contribute).
  template <class Row, class Scalar>
  static Mat3T<Scalar> curvature(const Row& w, const Vec3T<Scalar>& x) {
    Mat3T<Scalar> T = Mat3T<Scalar>::Zero();
    for (int r = 0; r < Derived::kParameters; ++r)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Exponents e = Derived::exponents[static_cast<std::size_t>(r)];
          const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
          Scalar c(e[ui]);
          if (e[ui] == 0) continue;
          e[ui] -= 1;
          if (e[uj] == 0) continue;
          c *= Scalar(e[uj]);
          e[uj] -= 1;
          T(i, j) += w(r) * c * detail::monomial(x, e);
        }
    return T;
  }
};

}  // namespace scalcal
