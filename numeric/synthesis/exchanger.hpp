// Fedorov's exchange for one model (exchange.hpp): P x P throughout, fixed-size, compiled once per
// model of this build in its own unit (numeric/synthesis/exchange_unit.cpp.in) for every criterion.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numeric/synthesis/exchange.hpp"

namespace scalcal {
namespace exchange_detail {

// A swap must gain more than rounding to count: otherwise two equal programs could swap forever.
constexpr double kGain = 1e-12;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The exchange for one model: P x P throughout, fixed-size.
template <class Model>
struct Exchanger {
  static constexpr int P = Model::kParameters;
  using Mat = InformationT<Model, double>;
  using Vec = RowT<Model, double>;
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, P>;

  // K' = (M + g g^T - h h^T)^-1 = K - [a b] S^-1 [a b]^T, a = K g, b = K h, as the criteria read it;
  // the spectrum only when asked for.
  struct SwappedInverse {
    const Mat& K;
    double det_K, trace_K;
    Vec a, b;
    Eigen::Matrix2d S_inv;
    double ratio;  // det M' / det M
    mutable std::optional<Vec> eigenvalues;

    int parameters() const { return P; }
    double det() const { return det_K / ratio; }
    double trace() const {
      return trace_K - (S_inv(0, 0) * a.squaredNorm() + 2 * S_inv(0, 1) * a.dot(b) + S_inv(1, 1) * b.squaredNorm());
    }
    double entry(int r, int c) const {
      return K(r, c) -
             (S_inv(0, 0) * a(r) * a(c) + S_inv(0, 1) * (a(r) * b(c) + b(r) * a(c)) + S_inv(1, 1) * b(r) * b(c));
    }
    double diagonal(int r) const { return entry(r, r); }
    double max_eigenvalue() const {
      if (!eigenvalues) {
        Eigen::Matrix<double, P, 2> U;
        U << a, b;
        const Mat Kp = K - U * S_inv * U.transpose();
        eigenvalues = Eigen::SelfAdjointEigenSolver<Mat>(Kp, Eigen::EigenvaluesOnly).eigenvalues();
      }
      return eigenvalues->maxCoeff();
    }
  };
  static_assert(InverseInformationView<SwappedInverse>);

  static Mat information(const std::vector<Vec3>& xs) {
    Mat M = Mat::Zero();
    for (const Vec3& x : xs) {
      const Vec h = Model::row(x);
      M.template selfadjointView<Eigen::Lower>().rankUpdate(h);
    }
    M.template triangularView<Eigen::StrictlyUpper>() = M.transpose();
    return M;
  }

  // K of M, or of M with a ridge far below any real information when M is singular: the ranking of
  // swaps then favours those that make more parameters identifiable. `ridged` says which.
  static Mat inverse_or_ridge(const Mat& M, bool& ridged, double& det_K) {
    Eigen::LLT<Mat> llt(M);
    const double scale = std::max(M.trace() / P, 1e-300);
    ridged =
        llt.info() != Eigen::Success || llt.matrixL().toDenseMatrix().diagonal().minCoeff() < 1e-7 * std::sqrt(scale);
    if (ridged) llt.compute(M + 1e-9 * scale * Mat::Identity());
    const Vec d = llt.matrixL().toDenseMatrix().diagonal();
    det_K = 1.0;
    for (int i = 0; i < P; ++i) det_K /= d(i) * d(i);
    return llt.solve(Mat::Identity());
  }

  template <class Crit>
  static double value_of(const Mat& K, double n) {
    const Vec eig = Eigen::SelfAdjointEigenSolver<Mat>(K, Eigen::EigenvaluesOnly).eigenvalues();
    return Crit::template value<Model>(InverseInformation<double, P>{K, eig}, n);
  }

  // The best candidate to put in place of `removed` (a zero row: nothing removed), and its value.
  template <class Crit>
  static std::pair<int, double> best_swap(const Mat& K, double det_K, const Rows& Hc, const Rows& HcK,
                                          const Vec& removed, double n) {
    const Vec b = K * removed;
    const double dh = removed.dot(b), trace_K = K.trace();
    std::pair<int, double> best{-1, kInfinity};
    for (Eigen::Index j = 0; j < Hc.rows(); ++j) {
      const Vec a = HcK.row(j).transpose();
      const double dg = Hc.row(j).dot(a.transpose()), dgh = removed.dot(a);
      Eigen::Matrix2d S;
      S << 1 + dg, dgh, dgh, -1 + dh;
      const double ratio = (1 + dg) * (1 - dh) + dgh * dgh;
      if (!(ratio > 1e-12)) continue;  // the swap would make M singular
      const SwappedInverse view{K, det_K, trace_K, a, b, S.inverse(), ratio, std::nullopt};
      const double v = Crit::template value<Model>(view, n);
      if (v < best.second) best = {static_cast<int>(j), v};
    }
    return best;
  }

  template <class Crit>
  static ExchangeResult exchange_with(const std::vector<Vec3>& candidates, std::vector<Vec3> positions, int fixed,
                                      int max_passes) {
    ExchangeResult out;
    const int N = static_cast<int>(positions.size());
    const double n = N;
    Rows Hc(static_cast<Eigen::Index>(candidates.size()), P);
    for (std::size_t j = 0; j < candidates.size(); ++j)
      Hc.row(static_cast<Eigen::Index>(j)) = Model::row(candidates[j]).transpose();
    Mat M = information(positions);
    // K, its value and Hc K change only with a swap: a position that keeps its place (every one of the
    // last pass) reuses them. Hc K is the exchange's one O(candidates) product (7 % of reproduce's CPU
    // when it was formed for every position).
    bool stale = true, ridged = false;
    double det_K = 0, current = 0;
    Mat K;
    Rows HcK;
    for (; out.passes < max_passes; ++out.passes) {
      bool changed = false;
      for (int i = fixed; i < N; ++i) {
        if (stale) {
          K = inverse_or_ridge(M, ridged, det_K);
          current = value_of<Crit>(K, n);
          HcK.noalias() = Hc * K;
          stale = false;
        }
        const Vec removed = Model::row(positions[static_cast<std::size_t>(i)]);
        const auto [j, v] = best_swap<Crit>(K, det_K, Hc, HcK, removed, n);
        // Ranked on a ridge, any rank gain shows as a drop by orders of magnitude.
        if (j >= 0 && v < current * (1 - kGain) &&
            candidates[static_cast<std::size_t>(j)] != positions[static_cast<std::size_t>(i)]) {
          positions[static_cast<std::size_t>(i)] = candidates[static_cast<std::size_t>(j)];
          M = information(positions);  // afresh: no drift from a chain of rank-one updates
          stale = true;
          changed = true;
          ++out.swaps;
        }
      }
      if (!changed) break;
    }
    if (stale) {  // a swap in the last pass allowed, or no pass at all
      K = inverse_or_ridge(M, ridged, det_K);
      current = value_of<Crit>(K, n);
    }
    out.value = ridged ? kInfinity : current;
    out.positions = std::move(positions);
    return out;
  }

  template <class Crit>
  static ExchangeResult greedy_with(const std::vector<Vec3>& candidates, const std::vector<Vec3>& given, int count) {
    std::vector<Vec3> positions = given;
    Rows Hc(static_cast<Eigen::Index>(candidates.size()), P);
    for (std::size_t j = 0; j < candidates.size(); ++j)
      Hc.row(static_cast<Eigen::Index>(j)) = Model::row(candidates[j]).transpose();
    for (int k = 0; k < count; ++k) {
      // Adding g is a swap that removes nothing (a zero row); the value is ranked at the final size
      // so that the ridge's scale does not change along the way.
      bool ridged;
      double det_K;
      const Mat K = inverse_or_ridge(information(positions), ridged, det_K);
      const Rows HcK = Hc * K;
      const auto [j, v] = best_swap<Crit>(K, det_K, Hc, HcK, Vec::Zero(), static_cast<double>(given.size() + count));
      positions.push_back(candidates[static_cast<std::size_t>(j >= 0 ? j : 0)]);
    }
    return exchange_with<Crit>(candidates, std::move(positions), static_cast<int>(given.size()), 100);
  }
};

}  // namespace exchange_detail

template <class Model>
ExchangeResult exchange_for(CriterionKind criterion, const std::vector<Vec3>& candidates, std::vector<Vec3> positions,
                            int fixed, int max_passes) {
  return visit_criterion(criterion, [&](auto C) {
    return exchange_detail::Exchanger<Model>::template exchange_with<decltype(C)>(candidates, std::move(positions),
                                                                                  fixed, max_passes);
  });
}

template <class Model>
ExchangeResult greedy_exchange_for(CriterionKind criterion, const std::vector<Vec3>& candidates,
                                   const std::vector<Vec3>& given, int count) {
  return visit_criterion(criterion, [&](auto C) {
    return exchange_detail::Exchanger<Model>::template greedy_with<decltype(C)>(candidates, given, count);
  });
}

}  // namespace scalcal
