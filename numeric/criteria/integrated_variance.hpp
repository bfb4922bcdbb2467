// I: the variance of the calibrated projection h(eta)^T X averaged over all orientations eta of the
// sphere, N integral h^T K h d sigma = N tr(K W) with W = integral h h^T d sigma (the uniform measure's
// information matrix): the worked example of numeric/criteria/ADDING_A_CRITERION.md. It is not in
// RegisteredCriteria, because no proof of its limit is checked yet; the fifth-criterion build
// (scripts/fifth_criterion.sh, -DSCALCAL_FIFTH_CRITERION=ON) registers it and runs it through every
// subcommand.
#pragma once
#include <cmath>

#include <Eigen/Cholesky>

#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/starts.hpp"
#include "numeric/model/design.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct IntegratedVarianceCriterion {
  static constexpr std::string_view name = "I";
  static constexpr std::string_view summary = "N tr(K W), W the sphere's mean of h h^T";
  static constexpr std::string_view label = "N tr(K W)";
  static constexpr std::string_view raw_name = "tr(K W)";
  static constexpr std::string_view raw_key = "tr_KW";
  // W is invariant under every rotation and reflection, so tr(K W) is too.
  static constexpr ProgramSymmetry symmetry = ProgramSymmetry::Orthogonal;
  using Form = SmoothForm;

  // W from the 20 face normals of the icosahedron, a spherical 5-design: exact for models whose
  // h h^T has degree 5 or less (the paper's model: degree 4).
  template <class Model, class Scalar>
  static InformationT<Model, Scalar> sphere_mean() {
    return information_matrix<Model>(ProgramTpl<Scalar>::icosahedral().positions) / Scalar(20);
  }

  template <class Model, InverseInformationView View, class Scalar>
  static Scalar value(const View& k, const Scalar& n) {
    const InformationT<Model, Scalar> W = sphere_mean<Model, Scalar>();
    Scalar t(0);
    for (int r = 0; r < Model::kParameters; ++r)
      for (int c = 0; c < Model::kParameters; ++c) t += k.entry(r, c) * W(c, r);
    return n * t;
  }

  template <class Model, InverseInformationView View>
  static auto raw(const View& k) {
    using Scalar = decltype(k.det());
    return value<Model>(k, Scalar(1));
  }

  static constexpr int default_starts(int positions) { return grown_starts(16, positions); }

  // No proof in proofs/ yet (the bound P, reached by spherical 4-designs, is derived in the test).
  template <class Model, class Scalar>
  static std::optional<CriterionLimitTpl<Scalar>> limit() {
    return std::nullopt;
  }

  template <class Scalar, int P>
  static bool objective(const Eigen::Matrix<Scalar, P, P>& M, int n, Scalar& out) {
    MatrixDerivatives<Scalar, P> d;
    if (!derivatives(M, n, d)) return false;
    out = d.value;
    return true;
  }

  // phi = N tr(K W): d phi = -N tr(K W K dM), so G = -N K W K, and dG = N (K dM (K W K) + (K W K) dM K).
  template <class Scalar, int P>
  static bool derivatives(const Eigen::Matrix<Scalar, P, P>& M, int n, MatrixDerivatives<Scalar, P>& d) {
    using Mat = Eigen::Matrix<Scalar, P, P>;
    Eigen::LLT<Mat> llt(M);
    if (llt.info() != Eigen::Success) return false;
    const Mat W = mean_for<P, Scalar>();
    d.A = llt.solve(Mat::Identity());
    d.A = (d.A + d.A.transpose()).eval() / Scalar(2);
    d.B = d.A * W * d.A;
    d.value = Scalar(n) * (d.A * W).trace();
    d.G = Scalar(-n) * d.B;
    d.c = Scalar(n);
    d.same_sides = false;
    return true;
  }

 private:
  // The solvers hand the criterion M alone; its size tells the model (the registered models' P differ).
  template <int P, class Scalar>
  static Eigen::Matrix<Scalar, P, P> mean_for() {
    return sphere_mean<ModelWithParameters<P>, Scalar>();
  }
};
static_assert(SmoothCriterion<IntegratedVarianceCriterion>);

}  // namespace scalcal
