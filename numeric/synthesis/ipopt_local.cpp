// Ipopt TNLP over x = (eta_1, ..., eta_N, extra...), with N norm constraints |eta_i|^2 = 1
// followed by the criterion's own constraints (dense rows), then one linear row axis . eta_i per
// position held in a zone of a restricted bench (fixed positions are fixed variables). The
// criterion is a SmoothProblem: the adapter never knows which one it runs.
#include "numeric/synthesis/ipopt_local.hpp"

#include "numeric/synthesis/ipopt_application.hpp"
#include "numeric/synthesis/solver_bookkeeping.hpp"

#include <functional>
#include <string>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

namespace scalcal {

namespace {

using Ipopt::Index;
using Ipopt::Number;

class ProgramNlp : public Ipopt::TNLP {
 public:
  ProgramNlp(const SmoothProblem& problem, std::vector<double> start, const PositionBounds* bounds,
             double settle_tolerance)
      : p_(problem), x0_(std::move(start)), n_(static_cast<int>(x0_.size())), settle_tolerance_(settle_tolerance) {
    const int coordinates = 3 * p_.positions();
    for (int r = 0; r < n_; ++r)
      for (int c = 0; c <= r; ++c)
        if ((r == c && r < coordinates) || p_.hessian_entry_used(r, c)) hessian_pattern_.emplace_back(r, c);
    if (bounds)
      for (int i = 0; i < p_.positions(); ++i) {
        const PositionBound& b = (*bounds)[static_cast<std::size_t>(i)];
        if (b.kind == PositionBound::Kind::Zone) zones_.push_back({i, b});
        if (b.kind == PositionBound::Kind::Fixed) fixed_.push_back(i);
      }
  }

  const std::vector<double>& solution() const { return xs_; }
  // Whether the run ended by the settle rule (LocalOptions::settle_tolerance), and Ipopt's unscaled
  // dual infeasibility at the last iteration.
  bool settled() const { return settled_ >= kSettledIterations; }
  double dual_infeasibility() const { return dual_infeasibility_; }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h, IndexStyleEnum& style) override {
    n = n_;
    m = p_.positions() + p_.constraints() + static_cast<int>(zones_.size());
    nnz_jac = 3 * p_.positions() + p_.constraints() * n_ + 3 * static_cast<int>(zones_.size());
    nnz_h = dense_hessian() ? n_ * (n_ + 1) / 2 : static_cast<Index>(hessian_pattern_.size());
    style = TNLP::C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = -2e19;
      x_u[i] = 2e19;
    }
    for (int i : fixed_)
      for (int c = 0; c < 3; ++c) x_l[3 * i + c] = x_u[3 * i + c] = x0_[static_cast<std::size_t>(3 * i + c)];
    for (int i = 0; i < p_.positions(); ++i) g_l[i] = g_u[i] = 1.0;
    // A fixed position's norm row loses all its variables: an inactive inequality (with a slack)
    // keeps the KKT system regular where a constant equality row would not.
    for (int i : fixed_) {
      g_l[i] = 0.0;
      g_u[i] = 4.0;
    }
    p_.constraint_bounds(g_l + p_.positions(), g_u + p_.positions());
    const int z0 = zone_row();
    for (std::size_t k = 0; k < zones_.size(); ++k) {
      g_l[z0 + static_cast<int>(k)] = zones_[k].bound.lower;
      g_u[z0 + static_cast<int>(k)] = zones_[k].bound.upper;
    }
    (void)m;
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index, bool init_lambda,
                          Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    for (Index i = 0; i < n; ++i) x[i] = x0_[static_cast<std::size_t>(i)];
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& f) override { return p_.objective(x, f, nullptr); }

  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    double f;
    std::fill(g, g + n, 0.0);
    return p_.objective(x, f, g);
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    for (int i = 0; i < p_.positions(); ++i)
      g[i] = x[3 * i] * x[3 * i] + x[3 * i + 1] * x[3 * i + 1] + x[3 * i + 2] * x[3 * i + 2];
    for (std::size_t k = 0; k < zones_.size(); ++k) {
      const int i = zones_[k].position;
      const Vec3& a = zones_[k].bound.axis;
      g[zone_row() + static_cast<int>(k)] = a(0) * x[3 * i] + a(1) * x[3 * i + 1] + a(2) * x[3 * i + 2];
    }
    return p_.constraints() == 0 || p_.constraint_values(x, g + p_.positions(), nullptr);
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* cols, Number* values) override {
    const int N = p_.positions(), mc = p_.constraints();
    if (values == nullptr) {
      Index k = 0;
      for (int i = 0; i < N; ++i)
        for (int c = 0; c < 3; ++c, ++k) {
          rows[k] = i;
          cols[k] = 3 * i + c;
        }
      for (int r = 0; r < mc; ++r)
        for (int j = 0; j < n_; ++j, ++k) {
          rows[k] = N + r;
          cols[k] = j;
        }
      for (std::size_t z = 0; z < zones_.size(); ++z)
        for (int c = 0; c < 3; ++c, ++k) {
          rows[k] = zone_row() + static_cast<int>(z);
          cols[k] = 3 * zones_[z].position + c;
        }
      return true;
    }
    for (int i = 0; i < 3 * N; ++i) values[i] = 2.0 * x[i];
    const int zone_values = 3 * N + mc * n_;
    for (std::size_t z = 0; z < zones_.size(); ++z)
      for (int c = 0; c < 3; ++c) values[zone_values + 3 * static_cast<int>(z) + c] = zones_[z].bound.axis(c);
    if (mc == 0) return true;
    std::vector<double> g(static_cast<std::size_t>(mc));
    std::fill(values + 3 * N, values + 3 * N + mc * n_, 0.0);
    return p_.constraint_values(x, g.data(), values + 3 * N);
  }

  // Lower triangle (dense, or the problem's pattern gathered from a dense buffer): the criterion's
  // Lagrangian Hessian plus 2 lambda_i I_3 from the norm constraints |eta_i|^2 = 1.
  bool eval_h(Index, const Number* x, bool, Number obj_factor, Index, const Number* lambda, bool, Index, Index* rows,
              Index* cols, Number* values) override {
    const bool dense = dense_hessian();
    if (values == nullptr) {
      if (!dense) {
        for (std::size_t k = 0; k < hessian_pattern_.size(); ++k) {
          rows[k] = hessian_pattern_[k].first;
          cols[k] = hessian_pattern_[k].second;
        }
        return true;
      }
      for (Index r = 0, k = 0; r < n_; ++r)
        for (Index c = 0; c <= r; ++c, ++k) {
          rows[k] = r;
          cols[k] = c;
        }
      return true;
    }
    if (!dense && p_.lagrangian_hessian_entries(x, obj_factor, lambda + p_.positions(), values)) {
      for (std::size_t k = 0; k < hessian_pattern_.size(); ++k) {
        const auto [r, c] = hessian_pattern_[k];
        if (r == c && r < 3 * p_.positions()) values[k] += 2.0 * lambda[r / 3];
      }
      return true;
    }
    if (!dense) lower_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_ + 1) / 2);
    Number* lower = dense ? values : lower_.data();
    if (!p_.lagrangian_hessian(x, obj_factor, lambda + p_.positions(), lower)) return false;
    for (Index r = 0; r < 3 * p_.positions(); ++r) lower[r * (r + 1) / 2 + r] += 2.0 * lambda[r / 3];
    if (!dense)
      for (std::size_t k = 0; k < hessian_pattern_.size(); ++k) {
        const auto [r, c] = hessian_pattern_[k];
        values[k] =
            lower[static_cast<std::size_t>(r) * static_cast<std::size_t>(r + 1) / 2 + static_cast<std::size_t>(c)];
      }
    return true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode mode, Index, Number objective, Number primal_infeasibility,
                             Number dual_infeasibility, Number, Number, Number, Number, Number, Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    if (settle_tolerance_ <= 0) return true;
    const bool still = mode == Ipopt::RegularMode && primal_infeasibility <= 1e-10 && dual_infeasibility <= 1e-6 &&
                       std::abs(objective - last_objective_) <= settle_tolerance_ * std::max(1.0, std::abs(objective));
    settled_ = still ? settled_ + 1 : 0;
    last_objective_ = objective;
    dual_infeasibility_ = dual_infeasibility;
    return !settled();
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*, const Number*, Index,
                         const Number*, const Number*, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    xs_.assign(x, x + n);
  }

 private:
  struct ZoneRow {
    int position;
    PositionBound bound;
  };
  int zone_row() const { return p_.positions() + p_.constraints(); }

  const SmoothProblem& p_;
  std::vector<double> x0_;
  std::vector<double> xs_;
  int n_;
  static constexpr int kSettledIterations = 3;
  double settle_tolerance_;
  double last_objective_ = std::numeric_limits<double>::infinity();
  int settled_ = 0;
  double dual_infeasibility_ = 0;
  std::vector<ZoneRow> zones_;  // linear rows: their Hessian is zero
  std::vector<int> fixed_;
  // The entries the problem says can be nonzero (with the norm constraints' diagonal), in Ipopt's
  // order; all of them when it declares none zero.
  std::vector<std::pair<Index, Index>> hessian_pattern_;
  std::vector<Number> lower_;  // the dense lower triangle a sparse pattern is gathered from

  bool dense_hessian() const {
    return hessian_pattern_.size() == static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_ + 1) / 2;
  }
};

}  // namespace

Ipopt::SmartPtr<Ipopt::IpoptApplication> ipopt_application() {
  // One application per thread, reused: creating and initialising Ipopt costs more than a whole
  // D optimisation at N = 18. (Sequential MUMPS is not thread-safe: synthesize() forks instead.)
  thread_local Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
  if (Ipopt::IsNull(app)) {
    // Links the replacements of the solvers' unread bookkeeping into every program that runs Ipopt.
    [[maybe_unused]] static const bool replaced = solver_bookkeeping_replaced();
    app = IpoptApplicationFactory();
    app->Options()->SetIntegerValue("print_level", 0);
    app->Options()->SetStringValue("sb", "yes");
    app->Options()->SetStringValue("mu_strategy", "adaptive");
    app->Options()->SetIntegerValue("min_refinement_steps", 0);  // refine only when the residual asks for it
    if (app->Initialize() != Ipopt::Solve_Succeeded) app = nullptr;
  }
  return app;
}

LocalResult run_ipopt(const SmoothProblem& problem, const Program& start, const LocalOptions& options,
                      const std::function<double(const Program&)>& value_of, const PositionBounds* bounds) {
  LocalResult out;
  out.program = start;
  out.value = value_of(start);
  if (!std::isfinite(out.value)) {
    out.summary.message = "rank-deficient start: no local model";
    return out;
  }
  Ipopt::SmartPtr<ProgramNlp> nlp = new ProgramNlp(problem, problem.start(start), bounds, options.settle_tolerance);
  const Ipopt::SmartPtr<Ipopt::IpoptApplication> app = ipopt_application();
  if (Ipopt::IsNull(app)) {
    out.summary.message = "Ipopt could not be initialised";
    return out;
  }
  app->Options()->SetStringValue("hessian_approximation", "exact");
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations > 0 ? options.max_iterations
                                              : problem.long_runs()      ? 300
                                                                         : 200);
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(nlp)));
  const bool settled = status == Ipopt::User_Requested_Stop && nlp->settled();
  const bool converged = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level || settled;
  if (Ipopt::IsValid(app->Statistics())) out.summary.iterations = app->Statistics()->IterationCount();
  if (settled) {
    char text[96];
    std::snprintf(text, sizeof text, "Ipopt: the objective settled (dual infeasibility %.2g)",
                  nlp->dual_infeasibility());
    out.summary.message = text;
  } else {
    out.summary.message = "Ipopt status " + std::to_string(static_cast<int>(status));
  }
  const std::vector<double>& x = nlp->solution();
  if (x.empty()) return out;
  Program result;
  for (int i = 0; i < start.size(); ++i)
    result.positions.push_back(Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]).normalized());
  const double value = value_of(result);
  if (std::isfinite(value)) {
    out.program = std::move(result);
    out.value = value;
    out.summary.termination = converged ? Termination::converged : Termination::not_converged;
  }
  return out;
}

}  // namespace scalcal
