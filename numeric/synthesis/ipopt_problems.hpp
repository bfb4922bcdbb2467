// The four criteria as smooth nonlinear programs over x = (eta_1..eta_N, extra variables):
// D: min log D; A: min A; S: min t s.t. N K(r,r) <= t; E: max s s.t. M/N - s I = L L^T.
// Values and first derivatives are exact (tests compare them with finite differences).
#pragma once
#include <memory>
#include <vector>

#include "numeric/criteria/criterion_kind.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

class SmoothProblem {
 public:
  explicit SmoothProblem(int positions) : positions_(positions) {}
  virtual ~SmoothProblem() = default;

  int positions() const { return positions_; }
  int variables() const { return 3 * positions_ + extra(); }
  virtual int extra() const { return 0; }        // variables after the 3N coordinates
  virtual int constraints() const { return 0; }  // rows after the N norm constraints

  // x for a program: its coordinates, then extra variables that make the start feasible.
  virtual std::vector<double> start(const Program& program) const;
  virtual void constraint_bounds(double* lower, double* upper) const { (void)lower; (void)upper; }
  // f(x) and, when grad is non-null, its gradient (grad is zeroed by the caller). False: undefined.
  virtual bool objective(const double* x, double& f, double* grad) const = 0;
  // The exact Hessian of obj_factor f + sum_r lambda_r g_r (the criterion's own constraints; the
  // norm constraints are the adapter's) over all variables, as the packed lower triangle, row by
  // row: (r, c), c <= r, at r(r+1)/2 + c. False: not supplied (quasi-Newton) or undefined at x.
  virtual bool has_hessian() const { return false; }
  virtual bool lagrangian_hessian(const double* x, double obj_factor, const double* lambda, double* lower) const {
    (void)x; (void)obj_factor; (void)lambda; (void)lower;
    return false;
  }
  // The criterion's constraints; jac (row-major, constraints() x variables(), zeroed by the caller).
  virtual bool constraint_values(const double* x, double* g, double* jac) const {
    (void)x; (void)g; (void)jac;
    return true;
  }

 protected:
  std::vector<Vec3> positions_of(const double* x) const;

 private:
  int positions_;
};

std::unique_ptr<SmoothProblem> make_problem(CriterionKind criterion, int positions);

}  // namespace scalcal
