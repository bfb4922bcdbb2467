// Certified lower bounds on a criterion's limit over a region, by weak duality: every bound below
// holds for EVERY measure on the region, given only an upper bound m on sup_x |C h(x)|^2 there
// (numeric/region/zone_sup.hpp proves one). C is built from a near-optimal K, but any C
// is valid, so rounding in building it costs tightness, never correctness; the bound itself is
// computed in interval arithmetic.
#pragma once
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <boost/numeric/interval.hpp>

#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/dual_kind.hpp"

namespace scalcal {

template <class C>
constexpr DualKind dual_kind() {
  if constexpr (requires { C::dual; })
    return C::dual;
  else if constexpr (MaxEigenvalueCriterion<C>)
    return DualKind::Spectral;
  else if constexpr (MaxDiagonalCriterion<C>)
    return DualKind::DiagonalSum;
  else
    return DualKind::None;
}

template <int P>
struct DualCertificate {
  DualKind kind = DualKind::None;
  Eigen::Matrix<double, Eigen::Dynamic, P> C;
  std::vector<int> rows;       // DiagonalSum: the parameter each row of C belongs to
  std::vector<double> gammas;  // DiagonalSum: its coefficient g_r (sqrt of the row's weight)

  // The certified lower bound on the normalised criterion of any measure, given m >= sup |C h|^2.
  double lower_bound(double m) const {
    namespace bn = boost::numeric;
    using I = bn::interval<double>;
    if (!(m > 0) || !std::isfinite(m)) return 0.0;
    const I mi(m);
    switch (kind) {
      case DualKind::Determinant: {  // C upper triangular: det W = prod C_ii^2
        I out(1.0);
        const I ratio = I(static_cast<double>(P)) / mi;
        for (int i = 0; i < P; ++i) out *= bn::square(I(C(i, i))) * ratio;
        return out.lower();
      }
      case DualKind::DiagonalSum: {
        I s(0.0);
        for (std::size_t j = 0; j < rows.size(); ++j) s += I(gammas[j]) * I(C(static_cast<int>(j), rows[j]));
        if (!(s.lower() > 0)) return 0.0;
        return (bn::square(s) / mi).lower();
      }
      case DualKind::Spectral: {
        I f(0.0);
        for (int j = 0; j < C.rows(); ++j)
          for (int k = 0; k < P; ++k) f += bn::square(I(C(j, k)));
        return (f / mi).lower();
      }
      case DualKind::None:
        break;
    }
    return 0.0;
  }
};

// The dual of a nonsmooth criterion's optimum when it is known exactly (numeric/region/
// measure_weights.hpp): the eigenvalue form's Z (>= 0, trace 1), the diagonal form's row weights.
template <int P>
struct ExactDual {
  Eigen::Matrix<double, P, P> Z = Eigen::Matrix<double, P, P>::Zero();
  std::vector<double> row_weights;
};

// The certificate built from K = M^-1 of a near-optimal measure (weights summing to 1). For the
// nonsmooth forms the dual comes from `exact` when given, else from the gradient of the power mean
// the measure was optimised with (numeric/region/optimal_measure.hpp; exponent `smoothing`):
// K(r,r)^(p-1) for rows and lambda^(p+1) for eigenvalues.
template <class Crit, class Model>
std::optional<DualCertificate<Model::kParameters>> dual_certificate(
    const Eigen::Matrix<double, Model::kParameters, Model::kParameters>& K, double smoothing,
    const ExactDual<Model::kParameters>* exact = nullptr) {
  constexpr int P = Model::kParameters;
  DualCertificate<P> out;
  out.kind = dual_kind<Crit>();
  switch (out.kind) {
    case DualKind::Determinant: {
      Eigen::LLT<Eigen::Matrix<double, P, P>> llt(K);
      if (llt.info() != Eigen::Success) return std::nullopt;
      out.C = llt.matrixU();  // W = U^T U = K
      return out;
    }
    case DualKind::DiagonalSum: {
      std::vector<int> rows;
      if constexpr (MaxDiagonalCriterion<Crit>)
        rows = Crit::template rows<Model>();
      else
        for (int r = 0; r < P; ++r) rows.push_back(r);
      std::vector<double> alpha(rows.size(), 1.0);
      if constexpr (MaxDiagonalCriterion<Crit>) {  // weights of the smoothed max, summing to 1
        if (exact && exact->row_weights.size() == rows.size()) {
          alpha = exact->row_weights;
        } else {
          double top = 0, total = 0;
          for (int r : rows) top = std::max(top, K(r, r));
          for (std::size_t j = 0; j < rows.size(); ++j)
            total += alpha[j] = std::pow(K(rows[j], rows[j]) / top, smoothing - 1.0);
          for (double& a : alpha) a /= total;
        }
      }
      out.C.resize(static_cast<Eigen::Index>(rows.size()), P);
      for (std::size_t j = 0; j < rows.size(); ++j) {
        out.gammas.push_back(std::sqrt(alpha[j]));
        out.C.row(static_cast<Eigen::Index>(j)) = out.gammas.back() * K.row(rows[j]);
      }
      out.rows = rows;
      return out;
    }
    case DualKind::Spectral: {
      if (exact && exact->Z.trace() > 0) {  // C = Z^(1/2)
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, P, P>> eig(exact->Z);
        out.C.resize(P, P);
        for (int j = 0; j < P; ++j)
          out.C.row(j) = std::sqrt(std::max(0.0, eig.eigenvalues()(j))) * eig.eigenvectors().col(j).transpose();
        return out;
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, P, P>> eig(K);
      const double top = eig.eigenvalues()(P - 1);
      std::vector<double> a(P);
      double total = 0;
      for (int j = 0; j < P; ++j) total += a[j] = std::pow(eig.eigenvalues()(j) / top, smoothing + 1.0);
      out.C.resize(P, P);
      for (int j = 0; j < P; ++j) out.C.row(j) = std::sqrt(a[j] / total) * eig.eigenvectors().col(j).transpose();
      return out;
    }
    case DualKind::None:
      break;
  }
  return std::nullopt;
}

}  // namespace scalcal
