// Products written as plain loops for the interval scalar: Eigen's product kernels give NaN
// entries with Boost's mpfi_float (seen in 9x9 products), so nothing certified goes through them.
#pragma once
#include <Eigen/Core>

namespace scalcal::certify_detail {

template <class A, class B>
auto times(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  using T = typename A::Scalar;
  Eigen::Matrix<T, A::RowsAtCompileTime, B::ColsAtCompileTime> out(a.rows(), b.cols());
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
      T acc(0);
      for (Eigen::Index k = 0; k < a.cols(); ++k) acc += a(i, k) * b(k, j);
      out(i, j) = acc;
    }
  return out;
}

// sum_i a(i) b(i) over vectors of equal length.
template <class A, class B>
typename A::Scalar inner(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  typename A::Scalar acc(0);
  for (Eigen::Index i = 0; i < a.size(); ++i) acc += a(i) * b(i);
  return acc;
}

// tr(A B) for square A, B.
template <class A, class B>
typename A::Scalar trace_of_product(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  typename A::Scalar acc(0);
  for (Eigen::Index k = 0; k < a.rows(); ++k)
    for (Eigen::Index l = 0; l < a.cols(); ++l) acc += a(k, l) * b(l, k);
  return acc;
}

// sum_ij A_ij B_ij = tr(A^T B) for A, B of equal shape.
template <class A, class B>
typename A::Scalar entrywise_inner(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  typename A::Scalar acc(0);
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) acc += a(i, j) * b(i, j);
  return acc;
}

// a b^T + b a^T.
template <class A, class B>
auto symmetric_outer(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  using T = typename A::Scalar;
  Eigen::Matrix<T, A::RowsAtCompileTime, A::RowsAtCompileTime> out(a.size(), a.size());
  for (Eigen::Index i = 0; i < a.size(); ++i)
    for (Eigen::Index j = 0; j < a.size(); ++j) out(i, j) = a(i) * b(j) + b(i) * a(j);
  return out;
}

}  // namespace scalcal::certify_detail
