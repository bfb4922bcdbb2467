// Evaluation of a program as the paper compares programs: K = (H^T H)^-1 and every registered
// criterion, normalised by N (D by N^P), and the RMS errors theta_q (eq. 7). A program whose H is
// rank-deficient is reported with its rank and the parameters it cannot identify; criteria are then
// +infinity, never a regularised number.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/SVD>

#include "numeric/criteria/design_svd.hpp"
#include "numeric/criteria/evaluation_models.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/model/design.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

template <class Scalar, class Model = Paper9Model>
struct EvaluationTpl {
  static constexpr int P = Model::kParameters;
  int positions = 0;
  int rank = 0;
  Scalar condition;  // 2-norm condition number of H^T H: lambda_max / lambda_min
  // Every registered criterion by CriterionKind index: normalised (D = N^P det K, A = N trace K,
  // E = N lambda_max(K), S = N max_r K(r,r)) and raw (det K, trace K, ...).
  std::array<Scalar, kCriterionCount> values, raw_values;
  // theta_q = sqrt(N max K(r,r)) over the parameters of each group (eq. 7, times sqrt N); NaN for a
  // group the model does not have.
  Scalar theta_bias, theta_scale, theta_nonorth, theta_cubic;
  InformationT<Model, Scalar> information;  // H^T H
  InformationT<Model, Scalar> K;            // (H^T H)^-1, zero when rank < P
  RowT<Model, Scalar> K_eigenvalues;        // ascending, zero when rank < P
  std::vector<int> unidentifiable;          // indices into Model::parameter_names, empty at full rank

  bool full_rank() const { return rank == P; }
  const Scalar& value(CriterionKind c) const { return values[static_cast<std::size_t>(c.index())]; }
  const Scalar& raw(CriterionKind c) const { return raw_values[static_cast<std::size_t>(c.index())]; }
  // By the criterion's registered name ("D"): for readability where one criterion is meant.
  const Scalar& value(std::string_view name) const { return value(*parse_criterion(name)); }
};

using Evaluation = EvaluationTpl<double>;

namespace detail {

// Everything comes from the SVD of H, not from an eigen-decomposition of H^T H: squaring H
// squares its condition number, and a nearly singular program would otherwise get a tiny or even
// negative eigenvalue (and so a negative det K or lambda_max K). With H = U diag(sigma) V^T,
// K = V diag(sigma^-2) V^T exactly. The rank uses the usual tolerance max(N, P) eps sigma_max;
// a parameter whose unit vector has a component in the null space is not identifiable.
template <class Model, class Scalar>
RowT<Model, Scalar> singular_values(const PositionsT<Scalar>& positions, EvaluationTpl<Scalar, Model>& ev,
                                    InformationT<Model, Scalar>& V) {
  constexpr int P = Model::kParameters;
  using std::sqrt;
  const auto H = design_matrix<Model>(positions);
  RowT<Model, Scalar> sigma = RowT<Model, Scalar>::Zero();
  if constexpr (std::is_same_v<Scalar, double>) {  // one SVD for every model (design_svd.hpp)
    Eigen::VectorXd s;
    Eigen::MatrixXd v;
    design_svd(H, s, v);
    sigma.head(s.size()) = s;
    V = v;
  } else {
    Eigen::JacobiSVD<Eigen::Matrix<Scalar, Eigen::Dynamic, P>> svd(H, Eigen::ComputeFullV);
    sigma.head(svd.singularValues().size()) = svd.singularValues();
    V = svd.matrixV();
  }
  const Scalar eps = Eigen::NumTraits<Scalar>::epsilon();
  const Scalar tol = Scalar(std::max<int>(static_cast<int>(positions.size()), P)) * eps * sigma(0);
  int rank = 0;
  for (int i = 0; i < P; ++i)
    if (sigma(i) > tol) ++rank;
  ev.rank = rank;
  ev.unidentifiable.clear();
  if (rank < P) {
    const auto null_space = V.rightCols(P - rank);
    const Scalar threshold = sqrt(eps);
    for (int r = 0; r < P; ++r)
      if (null_space.row(r).norm() > threshold) ev.unidentifiable.push_back(r);
  }
  return sigma;
}

template <class Model, class Scalar>
Scalar group_theta(const RowT<Model, Scalar>& diag, const Scalar& n, ParameterGroup g) {
  using std::sqrt;
  const std::vector<int> members = group_members<Model>(g);
  if (members.empty()) return std::numeric_limits<Scalar>::quiet_NaN();
  Scalar worst = diag(members.front());
  for (int r : members) worst = std::max(worst, Scalar(diag(r)));
  return sqrt(n * worst);
}

}  // namespace detail

template <class Model = Paper9Model, class Scalar>
EvaluationTpl<Scalar, Model> evaluate(const ProgramTpl<Scalar>& program) {
  constexpr int P = Model::kParameters;
  EvaluationTpl<Scalar, Model> ev;
  ev.positions = program.size();
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  ev.values.fill(inf);
  ev.raw_values.fill(inf);
  ev.theta_bias = ev.theta_scale = ev.theta_nonorth = ev.theta_cubic = inf;
  ev.condition = inf;
  ev.K.setZero();
  ev.K_eigenvalues.setZero();
  if (program.size() == 0) {  // nothing measured: nothing identifiable
    ev.information.setZero();
    for (int r = 0; r < P; ++r) ev.unidentifiable.push_back(r);
    return ev;
  }
  ev.information = information_matrix<Model>(program.positions);
  InformationT<Model, Scalar> V;
  const RowT<Model, Scalar> sigma = detail::singular_values(program.positions, ev, V);  // descending
  if (!ev.full_rank()) return ev;
  const RowT<Model, Scalar> inv_lambda = sigma.cwiseProduct(sigma).cwiseInverse();  // eigenvalues of K
  ev.K = V * inv_lambda.asDiagonal() * V.transpose();
  ev.K_eigenvalues = inv_lambda;
  const Scalar N(program.size());
  const InverseInformation<Scalar, P> k{ev.K, inv_lambda};
  for (CriterionKind c : kCriteria) {
    const auto i = static_cast<std::size_t>(c.index());
    ev.values[i] = visit_criterion(c, [&](auto C) { return decltype(C)::template value<Model>(k, N); });
    ev.raw_values[i] = visit_criterion(c, [&](auto C) { return Scalar(decltype(C)::template raw<Model>(k)); });
  }
  ev.condition = (sigma(0) / sigma(P - 1)) * (sigma(0) / sigma(P - 1));
  const RowT<Model, Scalar> diag = ev.K.diagonal();
  ev.theta_bias = detail::group_theta<Model>(diag, N, ParameterGroup::bias);
  ev.theta_scale = detail::group_theta<Model>(diag, N, ParameterGroup::scale);
  ev.theta_nonorth = detail::group_theta<Model>(diag, N, ParameterGroup::nonorth);
  ev.theta_cubic = detail::group_theta<Model>(diag, N, ParameterGroup::cubic);
  return ev;
}

// Every registered model in double is evaluated in many units (CLI, reproduce, synthesis), so it is
// instantiated once per model, in that model's generated evaluation unit (evaluation_unit.cpp.in);
// its SVD, once for every model, in design_svd.cpp.
#define SCALCAL_EVALUATE_INSTANCES(prefix, M) \
  prefix template EvaluationTpl<double, M> evaluate<M, double>(const ProgramTpl<double>&);
#define SCALCAL_EXTERN_EVALUATE(M) SCALCAL_EVALUATE_INSTANCES(extern, M)
SCALCAL_FOR_EACH_MODEL(SCALCAL_EXTERN_EVALUATE)
#undef SCALCAL_EXTERN_EVALUATE

// The normalised value of one registered criterion (+infinity when rank < P).
template <class Model = Paper9Model, class Scalar>
Scalar criterion_value(const ProgramTpl<Scalar>& program, CriterionKind c) {
  return evaluate<Model>(program).value(c);
}

// The normalised value of any criterion type, registered or not (+infinity when rank < P).
template <Criterion C, class Model = Paper9Model, class Scalar>
Scalar criterion_value(const ProgramTpl<Scalar>& program) {
  const EvaluationTpl<Scalar, Model> ev = evaluate<Model>(program);
  if (!ev.full_rank()) return std::numeric_limits<Scalar>::infinity();
  const InverseInformation<Scalar, Model::kParameters> k{ev.K, ev.K_eigenvalues};
  return C::template value<Model>(k, Scalar(program.size()));
}

}  // namespace scalcal
