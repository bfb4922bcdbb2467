// The Riemannian Hessian of a function of M = sum_i h(eta_i) h(eta_i)^T over N unit vectors, kept in
// its structure: a 2 x 2 block per position plus a coupling of rank at most Q = P(P+1)/2,
//   H = D + U^T W U,  U t = the entries m_ab (a >= b) of dM(t), the first-order change of M along t,
//   t^T U^T W U t = 2c tr(dM A dM B)   (d phi = tr(G dM), dG = c (A dM B + B dM A): criteria/criterion.hpp),
//   D_i = 2 B_i^T T(G h_i) B_i + 2 T_i^T G T_i - (eta_i . grad_i) I   (T_i = J_i B_i, B_i the tangent basis),
// which is SphereNewton's dense 2N x 2N Hessian term by term. Kept so, a product H t, a solve with
// H + mu I (Woodbury) and the inertia of H + mu I (Sylvester's law through the Schur complements of
// [[D, V^T], [V, -Sigma]], W = V^T Sigma V, Sigma = +-1: In(H) = In(D) + In(Sigma + V D^-1 V^T) - In(Sigma))
// cost O(N Q^2) instead of the O(N^3) of a dense factorisation: at N = 1000 a few milliseconds.
// Only the assembly depends on the model; the rest (StructuredHessianCore, structured_hessian.cpp)
// is compiled once for every model: it runs once per confirmed program, and its Q x Q and r x r
// eigen-decompositions cost some 9 s of compile time per model when their sizes are fixed.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "numeric/criteria/criterion.hpp"
#include "numeric/model/design.hpp"
#include "numeric/synthesis/sphere_newton.hpp"
#include "numeric/synthesis/symmetric_pairs.hpp"

namespace scalcal {

// H = D + U^T W U with U, W and D given: its product, its inertia and its solves, for any model.
class StructuredHessianCore {
 public:
  using VecX = Eigen::VectorXd;
  using MatX = Eigen::MatrixXd;
  using Basis = Eigen::Matrix<double, 3, 2>;
  struct Inertia {
    int negative = 0, zero = 0, positive = 0;
  };

  int size() const { return 2 * n_; }
  const VecX& gradient() const { return g_; }  // Riemannian, in the tangent bases
  const Basis& basis(int i) const { return bases_[static_cast<std::size_t>(i)]; }
  VecX apply(const VecX& t) const;  // H t
  MatX dense() const;               // H itself (tests)
  double mean_diagonal() const;     // trace H / 2N: the Hessian's scale

  // Prepares solve() and inertia() for H + mu I. False when a block of D + mu I or the Schur
  // complement is singular to rounding: another mu will do.
  bool factor(double mu);
  const Inertia& inertia() const { return inertia_; }
  VecX solve(const VecX& b) const;  // (H + mu I)^-1 b

 protected:
  void resize(int n, int q);  // n positions, q pairs
  void coupling(MatX W);      // W_, then V_ and sigma_

  int n_ = 0;
  std::vector<Basis> bases_;
  std::vector<Eigen::Matrix2d> D_;
  MatX U_;      // Q x 2N
  MatX W_;      // Q x Q
  MatX V_;      // r x 2N: |lambda_k|^1/2 e_k^T U over the r nonzero eigenpairs of W
  VecX sigma_;  // their signs
  VecX g_;
  // factor(mu):
  std::vector<Eigen::Matrix2d> Dinv_;
  MatX S_vectors_;
  VecX S_values_;
  Inertia inertia_;
};

template <class Model>
class StructuredHessian : public StructuredHessianCore {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int Q = P * (P + 1) / 2;
  using MatP = InformationT<Model, double>;

  // The model at eta for the derivatives d of the criterion there.
  void assemble(const std::vector<Vec3>& eta, const MatrixDerivatives<double, P>& d);

 private:
  static int pair(int a, int b) { return symmetric_pair(a, b); }
};

template <class Model>
void StructuredHessian<Model>::assemble(const std::vector<Vec3>& eta, const MatrixDerivatives<double, P>& d) {
  resize(static_cast<int>(eta.size()), Q);
  for (int i = 0; i < n_; ++i) {
    const Vec3& e = eta[static_cast<std::size_t>(i)];
    const RowT<Model, double> h = Model::row(e);
    const JacobianT<Model, double> J = Model::jacobian(e);
    const Basis& Bi = bases_[static_cast<std::size_t>(i)] = tangent_basis(e);
    const Eigen::Matrix<double, P, 2> T = J * Bi;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) U_.template block<1, 2>(pair(a, b), 2 * i) = T.row(a) * h(b) + h(a) * T.row(b);
    const RowT<Model, double> w = d.G * h;
    const Vec3 egrad = 2.0 * (J.transpose() * w);
    g_.template segment<2>(2 * i) = Bi.transpose() * egrad;
    D_[static_cast<std::size_t>(i)] = 2.0 * (Bi.transpose() * Model::curvature(w, e) * Bi) +
                                      2.0 * (T.transpose() * d.G * T) - e.dot(egrad) * Eigen::Matrix2d::Identity();
  }
  // W(q1, q2) = c [tr(S1 A S2 B) + tr(S1 B S2 A)] (symmetric_pairs.hpp).
  coupling(d.c * pair_trace_form<P>(d.A, d.B));
}

}  // namespace scalcal
