// Attainment as a square system: a program reaches the limit of D, A, E or S exactly when its
// moments of degree <= 4 equal those of the criterion's symmetric optimal measure (E[x^2 y^2] = b,
// E[x^4] = 1/3 - 2b, the rest 0; proofs/aes_limits.md, d_equality.md). On the sphere the 14
// quartic monomials other than z^4 and the 10 cubic ones span that space with the constant, so
// 24 equations; the program's surplus coordinates are held, 24 are solved for.
#pragma once
#include <array>
#include <vector>

#include "numeric/certify/free_coordinates.hpp"
#include "numeric/certify/interval.hpp"
#include "numeric/certify/sphere_chart.hpp"

namespace scalcal::certify_detail {

struct MomentSystem {
  static constexpr int kEquations = 24;
  const SphereChart* chart;
  FreeCoordinates coordinates;
  Interval b;  // E[x^2 y^2] of the optimal measure, enclosed (it is irrational for A and S)

  static std::vector<std::array<int, 3>> exponents() {
    std::vector<std::array<int, 3>> out;
    for (int degree : {4, 3})
      for (int a = degree; a >= 0; --a)
        for (int c = 0; c <= degree - a; ++c) {
          const int bb = degree - a - c;
          if (!(degree == 4 && c == 4)) out.push_back({a, bb, c});
        }
    return out;
  }

  template <class T>
  static T target(const std::array<int, 3>& k, const T& b) {
    const int even = (k[0] % 2 == 0) + (k[1] % 2 == 0) + (k[2] % 2 == 0);
    if (k[0] + k[1] + k[2] != 4 || even != 3) return T(0);
    const bool quartic = k[0] == 4 || k[1] == 4 || k[2] == 4;
    return quartic ? T(1) / T(3) - T(2) * b : b;
  }

  int size() const { return coordinates.size(); }

  // F (24) and its Jacobian in the free coordinates; the full Jacobian (24 x 2N) when all are free.
  template <class T>
  void eval(const Eigen::Matrix<T, -1, 1>& x, Eigen::Matrix<T, -1, 1>& F, Eigen::Matrix<T, -1, -1>* J) const {
    static const std::vector<std::array<int, 3>> ks = exponents();
    const auto z = coordinates.full(x);
    const int n = static_cast<int>(chart->e.size());
    const T weight = T(1) / T(n);
    const T bt = convert(b, T{});
    F.resize(kEquations);
    for (int k = 0; k < kEquations; ++k) F(k) = -target(ks[k], bt);
    if (J) J->setZero(kEquations, coordinates.size());
    for (int i = 0; i < n; ++i) {
      const auto e = chart->position<T>(i, z(2 * i), z(2 * i + 1));
      std::array<std::array<Jet2<T>, 5>, 3> pw;
      for (int a = 0; a < 3; ++a) {
        pw[a][0] = Jet2<T>::constant(T(1));
        for (int p = 1; p < 5; ++p) pw[a][p] = pw[a][p - 1] * e[a];
      }
      const int cu = coordinates.column[2 * i], cv = coordinates.column[2 * i + 1];
      for (int k = 0; k < kEquations; ++k) {
        const Jet2<T> m = pw[0][ks[k][0]] * pw[1][ks[k][1]] * pw[2][ks[k][2]];
        F(k) += m.f * weight;
        if (J && cu >= 0) (*J)(k, cu) += m.u * weight;
        if (J && cv >= 0) (*J)(k, cv) += m.v * weight;
      }
    }
  }

 private:
  static Real convert(const Interval& b, Real) { return mid(b); }
  static Interval convert(const Interval& b, Interval) { return b; }
  static double convert(const Interval& b, double) { return static_cast<double>(mid(b)); }
};

}  // namespace scalcal::certify_detail
