// The inverse information matrix K = (H^T H)^-1 as the criteria read it: a view with det K,
// trace K, its entries K(r,c) and lambda_max(K). Evaluation gives one built from the SVD of H; the random-search
// kernel gives its own from an LDL^T factorisation, so each criterion's value is written once.
#pragma once
#include <concepts>

#include <Eigen/Core>

namespace scalcal {

template <class V>
concept InverseInformationView = requires(const V& k, int r) {
  { k.parameters() } -> std::convertible_to<int>;
  k.det();
  k.trace();
  k.diagonal(r);
  k.entry(r, r);
  k.max_eigenvalue();
};

// K and its eigenvalues, both already computed.
template <class Scalar, int P>
struct InverseInformation {
  const Eigen::Matrix<Scalar, P, P>& K;
  const Eigen::Matrix<Scalar, P, 1>& eigenvalues;

  int parameters() const { return P; }
  Scalar det() const {
    Scalar out(1);
    for (int i = 0; i < P; ++i) out *= eigenvalues(i);
    return out;
  }
  Scalar trace() const { return eigenvalues.sum(); }
  Scalar diagonal(int r) const { return K(r, r); }
  Scalar entry(int r, int c) const { return K(r, c); }
  Scalar max_eigenvalue() const { return eigenvalues.maxCoeff(); }
};

}  // namespace scalcal
