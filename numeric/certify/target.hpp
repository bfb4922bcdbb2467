// What the certificates need to know of a criterion, taken from its type: the limit and the b =
// E[x^2 y^2] of its symmetric optimal measure as MPFI enclosures (the criterion's own limit<>()
// evaluated in interval arithmetic, not a double rounded), the symmetry that decides the rotation
// gauge, and which local-optimum certificate fits its form. Nothing is looked up by name.
#pragma once
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "numeric/certify/certify.hpp"
#include "numeric/certify/interval.hpp"
#include "numeric/criteria/a_criterion.hpp"
#include "numeric/criteria/criterion.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal::certify_detail {

// The local-optimum certificates numeric/certify has: the gradient of -log det M or of tr M^-1
// (critical_point.hpp), the KKT system of a max of diagonal entries of K (minimax_kkt.hpp) or of a
// multiple smallest eigenvalue of M (eigenvalue_kkt.hpp); none for any other smooth criterion.
enum class LocalCertificate { none, log_det, trace, max_diagonal, max_eigenvalue };

struct CertifyTarget {
  std::string name;
  Interval limit;                // the criterion's limit, enclosed
  Interval b;                    // E[x^2 y^2] of its symmetric optimal measure, enclosed
  bool rotations = false;        // invariant under O(3): the certificates hold the rotation gauge
  bool unique_moments = false;   // strictly convex in M: the optimal moment matrix is unique (D, A)
  bool uniform_moments = false;  // its optimal moment matrix is the uniform measure's (D: the 4-designs)
  LocalCertificate local = LocalCertificate::none;
  std::vector<int> rows;  // max_diagonal: the diagonal entries of K the criterion takes the max of
};

template <class C>
constexpr LocalCertificate local_certificate_of() {
  if constexpr (MaxDiagonalCriterion<C>)
    return LocalCertificate::max_diagonal;
  else if constexpr (MaxEigenvalueCriterion<C>)
    return LocalCertificate::max_eigenvalue;
  else if constexpr (kDeterminantOnly<C>)
    return LocalCertificate::log_det;  // N^9 det K: -log det M
  else if constexpr (std::is_same_v<C, ACriterion>)
    return LocalCertificate::trace;  // N tr K: tr M^-1
  else
    return LocalCertificate::none;
}

// The target of criterion C for the paper's model, at the current MPFI precision.
template <Criterion C>
CertifyTarget target_of() {
  const auto limit = C::template limit<Paper9Model, Interval>();
  if (!limit) throw NoKnownLimit(C::name);
  CertifyTarget t;
  t.name = std::string(C::name);
  t.limit = limit->value;
  t.b = limit->moment_b;
  t.rotations = C::symmetry == ProgramSymmetry::Orthogonal;
  t.local = local_certificate_of<C>();
  if constexpr (MaxDiagonalCriterion<C>) t.rows = C::template rows<Paper9Model>();
  // -log det M and tr M^-1 are strictly convex on positive definite M: one optimal moment matrix
  // (proofs/d_equality.md, aes_limits.md); the max-forms are not strictly convex.
  t.unique_moments = t.local == LocalCertificate::log_det || t.local == LocalCertificate::trace;
  // The D-optimal measure is the uniform one (proofs/d_limit.md): b = 1/15, the 4-designs.
  t.uniform_moments = t.local == LocalCertificate::log_det;
  return t;
}

}  // namespace scalcal::certify_detail
