// The nonlinear program a criterion is for Ipopt, as the adapter (ipopt_local.cpp) sees it: x = (eta_1..
// eta_N, extra variables), N norm constraints |eta_i|^2 = 1 (the adapter's) followed by the
// criterion's own rows; values, gradients and exact Lagrangian Hessians, dense or by a sparsity the
// problem declares.
#pragma once
#include <algorithm>
#include <utility>
#include <vector>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

class SmoothProblem {
 public:
  explicit SmoothProblem(int positions) : positions_(positions) {}
  virtual ~SmoothProblem() = default;

  int positions() const { return positions_; }
  int variables() const { return 3 * positions_ + extra(); }
  virtual int extra() const { return 0; }          // variables after the 3N coordinates
  virtual int constraints() const { return 0; }    // rows after the N norm constraints
  virtual bool long_runs() const { return true; }  // nonsmooth reformulations get a larger iteration cap

  // x for a program: its coordinates, then extra variables that make the start feasible.
  virtual std::vector<double> start(const Program& program) const {
    std::vector<double> x(static_cast<std::size_t>(variables()), 0.0);
    for (int i = 0; i < positions_; ++i)
      for (int c = 0; c < 3; ++c)
        x[static_cast<std::size_t>(3 * i + c)] = program.positions[static_cast<std::size_t>(i)](c);
    return x;
  }
  virtual void constraint_bounds(double* lower, double* upper) const {
    (void)lower;
    (void)upper;
  }
  // f(x) and, when grad is non-null, its gradient (grad is zeroed by the caller). False: undefined.
  virtual bool objective(const double* x, double& f, double* grad) const = 0;
  // The exact Hessian of obj_factor f + sum_r lambda_r g_r (the criterion's own constraints; the
  // norm constraints are the adapter's) over all variables, as the packed lower triangle, row by
  // row: (r, c), c <= r, at r(r+1)/2 + c. False: undefined at x.
  virtual bool lagrangian_hessian(const double* x, double obj_factor, const double* lambda, double* lower) const = 0;
  // False where entry (r, c), c <= r, of that Hessian is zero at every x: Ipopt then leaves it out of
  // the KKT matrix its linear solver factorises (E: 1.9x faster at N = 100 than declared dense).
  virtual bool hessian_entry_used(int r, int c) const {
    (void)r;
    (void)c;
    return true;
  }
  // The Hessian's entries straight into Ipopt's values, in the order of the pattern hessian_entry_used
  // declares (row by row, c <= r; the positions' diagonal always included), without the norm rows'
  // 2 lambda_i I, which the adapter adds. False: not provided, the adapter gathers from the dense
  // lagrangian_hessian (O(n^2) memory and time per evaluation).
  virtual bool lagrangian_hessian_entries(const double* x, double obj_factor, const double* lambda,
                                          double* values) const {
    (void)x;
    (void)obj_factor;
    (void)lambda;
    (void)values;
    return false;
  }
  // The criterion's constraints; jac (row-major, constraints() x variables(), zeroed by the caller).
  virtual bool constraint_values(const double* x, double* g, double* jac) const {
    (void)x;
    (void)g;
    (void)jac;
    return true;
  }

 protected:
  PositionsT<double> positions_of(const double* x) const {
    PositionsT<double> eta(static_cast<std::size_t>(positions_));
    for (int i = 0; i < positions_; ++i) eta[static_cast<std::size_t>(i)] = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    return eta;
  }
  static void scatter(const PositionsT<double>& grad, double* out) {
    for (std::size_t i = 0; i < grad.size(); ++i)
      for (int c = 0; c < 3; ++c) out[3 * i + static_cast<std::size_t>(c)] += grad[i](c);
  }
  // Writes factor * H (the 3N x 3N position block) into the packed lower triangle of all variables.
  static void pack_lower(const MatXT<double>& H, double factor, int variables, double* lower) {
    std::fill(lower, lower + variables * (variables + 1) / 2, 0.0);
    for (int r = 0, k = 0; r < H.rows(); ++r)
      for (int c = 0; c <= r; ++c, ++k) lower[k] = factor * H(r, c);
  }

 private:
  int positions_;
};

}  // namespace scalcal
