// The optimal measure of a criterion on a finite candidate set: weights w_i >= 0 summing to 1 that
// minimise the criterion of M(w) = sum_i w_i h_i h_i^T. The criterion enters only through a smooth
// objective and its descent matrix Z (d_i = h_i^T Z h_i = -d phi / d w_i); nonsmooth forms are
// smoothed by a power mean, sharpened as the weights settle. Multiplicative steps with backtracking.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/exchange_path.hpp"
#include "numeric/model/model.hpp"
#include "numeric/synthesis/symmetric_pairs.hpp"

namespace scalcal {

template <int P>
struct MeasureOnCandidates {
  std::vector<double> weights;  // one per candidate
  Eigen::Matrix<double, P, P> M, K;
  double objective = 0;        // of the last smoothing
  double equivalence_gap = 0;  // max_i d_i / sum_i w_i d_i - 1 on the candidates: 0 at the optimum
  int iterations = 0;
  double sharpness = 1;  // the power-mean exponent reached (nonsmooth forms)
};

// phi and Z of Crit at M (weights summing to 1); false when M is not positive definite.
template <class Crit, class Model>
bool measure_objective(const Eigen::Matrix<double, Model::kParameters, Model::kParameters>& M, double p, double& phi,
                       Eigen::Matrix<double, Model::kParameters, Model::kParameters>* Z) {
  constexpr int P = Model::kParameters;
  using Mat = Eigen::Matrix<double, P, P>;
  if constexpr (SmoothCriterion<Crit>) {
    // The value alone (the line search's 42 calls an iteration) skips the inverse's products; it
    // is the derivatives' value to the bit (D: the same log det; A: the trace of the inverse,
    // whose symmetrisation leaves the diagonal exact).
    if (!Z) return Crit::objective(M, 1, phi);
    MatrixDerivatives<double, P> d;
    if (!Crit::derivatives(M, 1, d)) return false;
    phi = d.value;
    if (Z) *Z = -d.G;
    return true;
  } else {
    Eigen::LLT<Mat> llt(M);
    if (llt.info() != Eigen::Success) return false;
    const Mat K = llt.solve(Mat::Identity());
    if constexpr (MaxEigenvalueCriterion<Crit>) {
      // log of the power mean of the eigenvalues of K: Z = K^(p+1) / tr K^p
      Eigen::SelfAdjointEigenSolver<Mat> eig(K);
      const auto& l = eig.eigenvalues();
      const double top = l(P - 1);
      double s = 0;
      for (int j = 0; j < P; ++j) s += std::pow(l(j) / top, p);
      phi = std::log(top) + std::log(s) / p;
      if (Z) {
        Eigen::Matrix<double, P, 1> c;
        for (int j = 0; j < P; ++j) c(j) = l(j) * std::pow(l(j) / top, p) / s;
        *Z = eig.eigenvectors() * c.asDiagonal() * eig.eigenvectors().transpose();
      }
      return true;
    } else {
      static_assert(MaxDiagonalCriterion<Crit>, "measure_objective: a criterion of an unknown form");
      const std::vector<int> rows = Crit::template rows<Model>();
      double top = 0, s = 0;
      for (int r : rows) top = std::max(top, K(r, r));
      for (int r : rows) s += std::pow(K(r, r) / top, p);
      phi = std::log(top) + std::log(s) / p;
      if (Z) {
        Z->setZero();
        for (int r : rows) *Z += (std::pow(K(r, r) / top, p - 1) / (top * s)) * K.col(r) * K.col(r).transpose();
      }
      return true;
    }
  }
}

// Each candidate's products h_a h_b (b <= a, at symmetric_pair(a, b)): M(w) is then one
// matrix-vector product and so are the sensitivities h_i^T Z h_i, with Q of the P^2 entries each
// and no packing of a general matrix product (which took a third of the A limit on cap:90).
template <int P>
struct CandidateProducts {
  static constexpr int Q = P * (P + 1) / 2;
  using Mat = Eigen::Matrix<double, P, P>;
  Eigen::Matrix<double, Eigen::Dynamic, Q> products;

  explicit CandidateProducts(const Eigen::Matrix<double, P, Eigen::Dynamic>& H) : products(H.cols(), Q) {
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) products.col(symmetric_pair(a, b)) = H.row(a).cwiseProduct(H.row(b)).transpose();
  }
  Mat information(const Eigen::ArrayXd& v) const {
    const Eigen::Matrix<double, Q, 1> m = products.transpose() * v.matrix();
    Mat out;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) out(a, b) = out(b, a) = m(symmetric_pair(a, b));
    return out;
  }
  // h_i^T Z h_i for every candidate (Z symmetric: its lower triangle, off the diagonal twice).
  Eigen::ArrayXd sensitivities(const Mat& Z) const {
    Eigen::Matrix<double, Q, 1> z;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) z(symmetric_pair(a, b)) = a == b ? Z(a, a) : Z(a, b) + Z(b, a);
    return (products * z).array();
  }
};

// The minimum of f on [0, hi] by 40 golden-section steps: the point and its value.
template <class F>
std::pair<double, double> golden_section_minimum(const F& f, double hi) {
  double lo = 0;
  const double golden = 0.5 * (std::sqrt(5.0) - 1);
  double a1 = hi - golden * (hi - lo), a2 = lo + golden * (hi - lo), f1 = f(a1), f2 = f(a2);
  for (int s = 0; s < 40; ++s) {
    if (f1 <= f2) {
      hi = a2;
      a2 = a1;
      f2 = f1;
      a1 = hi - golden * (hi - lo);
      f1 = f(a1);
    } else {
      lo = a1;
      a1 = a2;
      f1 = f2;
      a2 = lo + golden * (hi - lo);
      f2 = f(a2);
    }
  }
  return {f1 <= f2 ? a1 : a2, std::min(f1, f2)};
}

// A vertex exchange (Boehning 1986; Yu's cocktail algorithm 2011): mass moves from the support
// point with the least d to the candidate with the most, by a golden-section line search. The
// multiplicative step alone crawls once many candidates crowd along a circle. (Smooth forms
// only: a smoothed nonsmooth form's line search costs an eigen-decomposition per trial, and
// its weights are made exact afterwards anyway: measure_weights.hpp.)
template <class Crit, class Model>
void vertex_exchange(const Eigen::Matrix<double, Model::kParameters, Eigen::Dynamic>& H,
                     const CandidateProducts<Model::kParameters>& c, double p, Eigen::ArrayXd& w,
                     Eigen::Matrix<double, Model::kParameters, Model::kParameters>& M, double& phi,
                     Eigen::Matrix<double, Model::kParameters, Model::kParameters>& Z) {
  constexpr int P = Model::kParameters;
  using Mat = Eigen::Matrix<double, P, P>;
  const Eigen::ArrayXd dv = c.sensitivities(Z);
  Eigen::Index j = 0, k = -1;
  dv.maxCoeff(&j);
  for (Eigen::Index i = 0; i < w.size(); ++i)
    if (w(i) > 0 && i != j && (k < 0 || dv(i) < dv(k))) k = i;
  if (k < 0 || dv(j) <= dv(k)) return;
  // The criterion's value along M + a (h_j h_j^T - h_k h_k^T): in O(1) from one factorisation of M
  // where it offers that (exchange_path.hpp), else a factorisation per trial.
  constexpr bool along_path = requires(const ExchangePath& e, double x) { Crit::objective_along(e, 1, x, x, x); };
  ExchangePath path;
  Mat delta;
  if constexpr (along_path)
    path = exchange_path<P>(Eigen::LLT<Mat>(M), H.col(j), H.col(k));
  else
    delta = H.col(j) * H.col(j).transpose() - H.col(k) * H.col(k).transpose();
  const auto phi_at = [&](double a) {
    double v = INFINITY;
    if constexpr (along_path) return Crit::objective_along(path, 1, phi, a, v) ? v : INFINITY;
    return measure_objective<Crit, Model>(M + a * delta, p, v, nullptr) ? v : INFINITY;
  };
  const auto [a, fa] = golden_section_minimum(phi_at, w(k));
  if (fa < phi) {
    w(j) += a;
    w(k) = std::max(0.0, w(k) - a);
    M = c.information(w);
    measure_objective<Crit, Model>(M, p, phi, &Z);
  }
}

// Continues from `start` (its weights, or uniform when empty). max_iterations bounds the work;
// tolerance is on the equivalence gap.
template <class Crit, class Model>
MeasureOnCandidates<Model::kParameters> optimal_measure(const std::vector<Vec3>& candidates,
                                                        const std::vector<double>& start = {},
                                                        int max_iterations = 3000, double tolerance = 1e-9) {
  constexpr int P = Model::kParameters;
  using Mat = Eigen::Matrix<double, P, P>;
  const int n = static_cast<int>(candidates.size());
  Eigen::Matrix<double, P, Eigen::Dynamic> H(P, n);
  for (int i = 0; i < n; ++i) H.col(i) = Model::row(candidates[static_cast<std::size_t>(i)]);
  const CandidateProducts<P> c(H);
  Eigen::ArrayXd w = Eigen::ArrayXd::Constant(n, 1.0 / n);
  if (static_cast<int>(start.size()) == n) {
    for (int i = 0; i < n; ++i) w(i) = std::max(start[static_cast<std::size_t>(i)], 1e-12 / n);
    w /= w.sum();
  }
  constexpr bool smooth = SmoothCriterion<Crit>;
  MeasureOnCandidates<P> out;
  double p = smooth ? 1.0 : 8.0;
  const double p_final = 65536.0;  // the smoothing bias is O(1/p) of the value
  double step = 1.0;
  Mat M = c.information(w), Z;
  double phi = 0;
  if (!measure_objective<Crit, Model>(M, p, phi, &Z)) {
    out.weights.assign(w.data(), w.data() + n);
    out.M = M;
    out.equivalence_gap = INFINITY;
    return out;
  }
  // Each sharpening gets a bounded share of the work: the smoothed optimum moves by O(1/p), so
  // settling an early stage exactly is wasted.
  constexpr int kStageIterations = 200;
  int it = 0, stage_start = 0;
  for (; it < max_iterations; ++it) {
    const Eigen::ArrayXd d = c.sensitivities(Z).max(0.0);
    const double average = (w * d).sum();
    const double gap = d.maxCoeff() / average - 1.0;
    out.equivalence_gap = gap;
    if (gap < tolerance) {
      if (smooth || p >= p_final) break;
      p = std::min(p_final, p * 2.0);  // settled at this smoothing: sharpen
      stage_start = it;
      measure_objective<Crit, Model>(M, p, phi, &Z);
      continue;
    }
    if (!smooth && p < p_final && (gap < 1e-3 || it - stage_start >= kStageIterations)) {
      p = std::min(p_final, p * 2.0);
      stage_start = it;
      measure_objective<Crit, Model>(M, p, phi, &Z);
      continue;
    }
    bool moved = false;
    for (int tries = 0; tries < 30 && !moved; ++tries) {
      Eigen::ArrayXd v = w * (d / average).pow(step);
      v /= v.sum();
      const Mat Mv = c.information(v);
      double phi_v = 0;
      Mat Zv;
      if (measure_objective<Crit, Model>(Mv, p, phi_v, &Zv) && phi_v <= phi) {
        w = v;
        M = Mv;
        phi = phi_v;
        Z = Zv;
        moved = true;
        step = std::min(4.0, step * 1.5);
      } else {
        step *= 0.5;
      }
    }
    if (!moved) break;  // no descent along the multiplicative direction at rounding level
    if constexpr (smooth) vertex_exchange<Crit, Model>(H, c, p, w, M, phi, Z);
  }
  out.iterations = it;
  out.sharpness = p;
  out.weights.assign(w.data(), w.data() + n);
  out.M = M;
  out.K = M.llt().solve(Mat::Identity());
  out.objective = phi;
  return out;
}

}  // namespace scalcal
