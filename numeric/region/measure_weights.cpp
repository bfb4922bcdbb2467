// Optimal weights of a criterion on a finite candidate set (measure_weights.hpp).
#include "numeric/region/measure_weights.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <IpTNLP.hpp>

#include "numeric/synthesis/ipopt_application.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

using Ipopt::Index;
using Ipopt::Number;
using Model = Paper9Model;
constexpr int P = Model::kParameters;
constexpr int kPairs = P * (P + 1) / 2;
constexpr double kInf = 2e19;

int pair(int a, int b) { return a >= b ? a * (a + 1) / 2 + b : b * (b + 1) / 2 + a; }

// Variables w (n), then the form's extras; rows: sum w = 1, then the form's constraints (dense).
// The smooth form has no extras and no constraints of its own; its exact Hessian is n x n dense,
// d^2 phi / dw_i dw_j = 2 c (h_i^T A h_j)(h_i^T B h_j).
class WeightsNlp : public Ipopt::TNLP {
 public:
  using Form = WeightForm;

  WeightsNlp(Form form, const std::vector<Vec3>& candidates, const std::vector<double>& start, std::vector<int> rows,
             SmoothObjective objective = {})
      : form_(form), n_(static_cast<int>(candidates.size())), rows_(std::move(rows)), objective_(std::move(objective)) {
    for (const Vec3& x : candidates) h_.push_back(Model::row(x));
    x0_ = start;
    const Mat9 M = information(start.data());
    // The extras are scaled to about 1 (on a small cap lambda_min(M) is 1e-6 and K(r,r) 1e6), so
    // that Ipopt's tolerances, and hence the multipliers the certificate is built from, are
    // relative ones.
    if (form_ == Form::Smooth) {
      // no extras
    } else if (form_ == Form::Eigenvalue) {
      scale_ = 1.0 / Eigen::SelfAdjointEigenSolver<Mat9>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
      const double s = 0.5;
      const Mat9 L = Eigen::LLT<Mat9>(scale_ * M - s * Mat9::Identity()).matrixL();
      x0_.push_back(s);
      for (int p = 0; p < kPairs; ++p) x0_.push_back(0);
      for (int a = 0; a < P; ++a)
        for (int b = 0; b <= a; ++b) x0_[static_cast<std::size_t>(n_ + 1 + pair(a, b))] = L(a, b);
    } else {
      const Mat9 K = M.llt().solve(Mat9::Identity());
      double top = 0;
      for (int r : rows_) top = std::max(top, K(r, r));
      scale_ = 1.0 / top;
      x0_.push_back(1.01);
    }
    variables_ = static_cast<int>(x0_.size());
  }

  int constraints() const {
    return form_ == Form::Eigenvalue ? kPairs : form_ == Form::Diagonal ? static_cast<int>(rows_.size()) : 0;
  }
  const std::vector<double>& solution() const { return xs_; }
  const std::vector<double>& multipliers() const { return lambda_; }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h, IndexStyleEnum& style) override {
    n = variables_;
    m = 1 + constraints();
    nnz_jac = n_ + constraints() * variables_;
    nnz_h = form_ == Form::Eigenvalue ? kPairs * (kPairs + 1) / 2 : n_ * (n_ + 1) / 2;
    style = TNLP::C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = i < n_ ? 0.0 : -kInf;
      x_u[i] = i < n_ ? 1.0 : kInf;
    }
    g_l[0] = g_u[0] = 1.0;
    for (int r = 0; r < constraints(); ++r) {
      g_l[1 + r] = form_ == Form::Eigenvalue ? 0.0 : -kInf;
      g_u[1 + r] = 0.0;
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index, bool init_lambda,
                          Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    std::copy(x0_.begin(), x0_.begin() + n, x);
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& f) override {
    if (form_ == Form::Smooth) {
      MatrixDerivatives<double, P> d;
      if (!objective_(information(x), d)) return false;
      f = d.value;
      return true;
    }
    f = form_ == Form::Eigenvalue ? -x[n_] : x[n_];
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    std::fill(g, g + n, 0.0);
    if (form_ == Form::Smooth) {  // d phi / d w_i = h_i^T G h_i
      MatrixDerivatives<double, P> d;
      if (!objective_(information(x), d)) return false;
      for (int i = 0; i < n_; ++i) g[i] = h_[static_cast<std::size_t>(i)].dot(d.G * h_[static_cast<std::size_t>(i)]);
      return true;
    }
    g[n_] = form_ == Form::Eigenvalue ? -1.0 : 1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    g[0] = 0;
    for (int i = 0; i < n_; ++i) g[0] += x[i];
    if (form_ == Form::Smooth) return true;
    const Mat9 M = information(x);
    if (form_ == Form::Eigenvalue) {
      const Mat9 L = lower(x), LLt = L * L.transpose();
      for (int a = 0; a < P; ++a)
        for (int b = 0; b <= a; ++b) g[1 + pair(a, b)] = scale_ * M(a, b) - (a == b ? x[n_] : 0.0) - LLt(a, b);
      return true;
    }
    Eigen::LLT<Mat9> llt(M);
    if (llt.info() != Eigen::Success) return false;
    const Mat9 K = llt.solve(Mat9::Identity());
    for (std::size_t r = 0; r < rows_.size(); ++r) g[1 + r] = scale_ * K(rows_[r], rows_[r]) - x[n_];
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* irow, Index* jcol, Number* values) override {
    if (values == nullptr) {
      Index k = 0;
      for (int i = 0; i < n_; ++i, ++k) {
        irow[k] = 0;
        jcol[k] = i;
      }
      for (int r = 0; r < constraints(); ++r)
        for (int j = 0; j < variables_; ++j, ++k) {
          irow[k] = 1 + r;
          jcol[k] = j;
        }
      return true;
    }
    std::fill(values, values + n_, 1.0);
    if (form_ == Form::Smooth) return true;
    double* J = values + n_;
    std::fill(J, J + constraints() * variables_, 0.0);
    if (form_ == Form::Eigenvalue) {
      const Mat9 L = lower(x);
      for (int a = 0; a < P; ++a)
        for (int b = 0; b <= a; ++b) {
          double* row = J + pair(a, b) * variables_;
          for (int i = 0; i < n_; ++i)
            row[i] = scale_ * h_[static_cast<std::size_t>(i)](a) * h_[static_cast<std::size_t>(i)](b);
          if (a == b) row[n_] = -1.0;
          for (int m = 0; m <= b; ++m) {
            row[n_ + 1 + pair(a, m)] -= L(b, m);
            row[n_ + 1 + pair(b, m)] -= L(a, m);
          }
        }
      return true;
    }
    Eigen::LLT<Mat9> llt(information(x));
    if (llt.info() != Eigen::Success) return false;
    const Mat9 K = llt.solve(Mat9::Identity());
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      double* row = J + static_cast<int>(r) * variables_;
      const Vec9 k = K.col(rows_[r]);
      for (int i = 0; i < n_; ++i) {
        const double t = k.dot(h_[static_cast<std::size_t>(i)]);
        row[i] = -scale_ * t * t;
      }
      row[n_] = -1.0;
    }
    return true;
  }

  // Eigenvalue form: only L enters quadratically, d^2/dL(a,m) dL(b,m) = -2 Lambda(a,b).
  // Diagonal form: d^2 K(r,r) / dw_i dw_j = 2 (k_r . h_i)(h_i^T K h_j)(h_j . k_r).
  bool eval_h(Index, const Number* x, bool, Number obj_factor, Index, const Number* lambda, bool, Index, Index* irow,
              Index* jcol, Number* values) override {
    const int base = form_ == Form::Eigenvalue ? n_ + 1 : 0;
    const int size = form_ == Form::Eigenvalue ? kPairs : n_;
    if (values == nullptr) {
      for (int r = 0, k = 0; r < size; ++r)
        for (int c = 0; c <= r; ++c, ++k) {
          irow[k] = base + r;
          jcol[k] = base + c;
        }
      return true;
    }
    std::fill(values, values + size * (size + 1) / 2, 0.0);
    const auto at = [values](int r, int c) -> double& {
      return r >= c ? values[r * (r + 1) / 2 + c] : values[c * (c + 1) / 2 + r];
    };
    if (form_ == Form::Smooth) {
      MatrixDerivatives<double, P> d;
      if (!objective_(information(x), d)) return false;
      Eigen::MatrixXd Hc(n_, P);
      for (int i = 0; i < n_; ++i) Hc.row(i) = h_[static_cast<std::size_t>(i)].transpose();
      const Eigen::MatrixXd HA = Hc * d.A, HB = Hc * d.B;
      const Eigen::MatrixXd GA = HA * Hc.transpose(), GB = HB * Hc.transpose();
      for (int i = 0; i < n_; ++i)
        for (int j = 0; j <= i; ++j) at(i, j) = obj_factor * 2 * d.c * GA(i, j) * GB(i, j);
      return true;
    }
    if (form_ == Form::Eigenvalue) {
      Mat9 Lambda;
      for (int a = 0; a < P; ++a)
        for (int b = 0; b <= a; ++b)
          Lambda(a, b) = Lambda(b, a) = a == b ? lambda[1 + pair(a, b)] : 0.5 * lambda[1 + pair(a, b)];
      for (int m = 0; m < P; ++m)
        for (int a = m; a < P; ++a)
          for (int b = m; b <= a; ++b) at(pair(a, m), pair(b, m)) = -2.0 * Lambda(a, b);
      return true;
    }
    Eigen::LLT<Mat9> llt(information(x));
    if (llt.info() != Eigen::Success) return false;
    const Mat9 K = llt.solve(Mat9::Identity());
    Eigen::MatrixXd Hc(n_, P);
    for (int i = 0; i < n_; ++i) Hc.row(i) = h_[static_cast<std::size_t>(i)].transpose();
    const Eigen::MatrixXd G = Hc * K * Hc.transpose();               // h_i^T K h_j
    Eigen::MatrixXd T(n_, static_cast<Eigen::Index>(rows_.size()));  // k_r . h_i
    Eigen::VectorXd twice_lambda(static_cast<Eigen::Index>(rows_.size()));
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      T.col(static_cast<Eigen::Index>(r)) = Hc * K.col(rows_[r]);
      twice_lambda(static_cast<Eigen::Index>(r)) = 2.0 * scale_ * lambda[1 + r];
    }
    const Eigen::MatrixXd TT = T * twice_lambda.asDiagonal() * T.transpose();
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j <= i; ++j) at(i, j) = TT(i, j) * G(i, j);
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*, const Number*, Index m,
                         const Number*, const Number* lambda, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    xs_.assign(x, x + n);
    lambda_.assign(lambda, lambda + m);
    status_ = status;
  }

  bool succeeded() const { return status_ == Ipopt::SUCCESS || status_ == Ipopt::STOP_AT_ACCEPTABLE_POINT; }

 private:
  Mat9 information(const double* w) const {
    Mat9 M = Mat9::Zero();
    for (int i = 0; i < n_; ++i) M.selfadjointView<Eigen::Lower>().rankUpdate(h_[static_cast<std::size_t>(i)], w[i]);
    M.triangularView<Eigen::StrictlyUpper>() = M.transpose();
    return M;
  }
  Mat9 lower(const double* x) const {
    Mat9 L = Mat9::Zero();
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) L(a, b) = x[n_ + 1 + pair(a, b)];
    return L;
  }

  Form form_;
  int n_, variables_ = 0;
  double scale_ = 1.0;
  std::vector<int> rows_;
  std::vector<Vec9> h_;
  SmoothObjective objective_;
  std::vector<double> x0_, xs_, lambda_;
  Ipopt::SolverReturn status_ = Ipopt::INTERNAL_ERROR;
};

}  // namespace

std::optional<ExactWeights> exact_weights(WeightForm form, const std::vector<Vec3>& candidates,
                                          const std::vector<double>& start, const std::vector<int>& rows,
                                          const SmoothObjective& objective) {
  const int n = static_cast<int>(candidates.size());
  // The solve runs in a child process: Ipopt's MUMPS state must not be inherited by later forks.
  const int size = 1 + n + 81 + static_cast<int>(rows.size());
  const std::vector<double> packed = run_in_child(size, [&] {
    std::vector<double> out(static_cast<std::size_t>(size), 0.0);
    Ipopt::SmartPtr<WeightsNlp> nlp = new WeightsNlp(form, candidates, start, rows, objective);
    const Ipopt::SmartPtr<Ipopt::IpoptApplication> app = ipopt_application();
    if (Ipopt::IsNull(app)) return out;
    app->Options()->SetStringValue("hessian_approximation", "exact");
    app->Options()->SetNumericValue("tol", 1e-12);
    app->Options()->SetIntegerValue("max_iter", 500);
    app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(nlp)));
    if (!nlp->succeeded() || nlp->solution().empty()) return out;
    out[0] = 1.0;
    for (int i = 0; i < n; ++i)
      out[static_cast<std::size_t>(1 + i)] = std::max(0.0, nlp->solution()[static_cast<std::size_t>(i)]);
    const std::vector<double>& lambda = nlp->multipliers();
    if (form == WeightForm::Eigenvalue) {
      for (int a = 0; a < P; ++a)
        for (int b = 0; b < P; ++b)  // Z = -Lambda, off-diagonal multipliers halved
          out[static_cast<std::size_t>(1 + n + 9 * a + b)] =
              -(a == b ? 1.0 : 0.5) * lambda[static_cast<std::size_t>(1 + pair(a, b))];
    } else if (form == WeightForm::Diagonal) {
      for (std::size_t r = 0; r < rows.size(); ++r)
        out[static_cast<std::size_t>(1 + n + 81) + r] = std::max(0.0, lambda[1 + r]);
    }
    return out;
  });
  if (packed[0] != 1.0) return std::nullopt;
  ExactWeights w;
  w.summary.termination = Termination::converged;
  w.summary.message = "Ipopt solved the weights problem";
  w.weights.assign(packed.begin() + 1, packed.begin() + 1 + n);
  double total = 0;
  for (double v : w.weights) total += v;
  for (double& v : w.weights) v /= total;
  w.dual = Mat9::Zero();
  if (form == WeightForm::Eigenvalue) {
    for (int a = 0; a < P; ++a)
      for (int b = 0; b < P; ++b) w.dual(a, b) = packed[static_cast<std::size_t>(1 + n + 9 * a + b)];
    // Any Z >= 0 gives a valid certificate: clip the multipliers' rounding to the PSD cone.
    Eigen::SelfAdjointEigenSolver<Mat9> eig(w.dual);
    const Vec9 l = eig.eigenvalues().cwiseMax(0.0);
    w.dual = eig.eigenvectors() * l.asDiagonal() * eig.eigenvectors().transpose();
    if (!(w.dual.trace() > 0)) return std::nullopt;
    w.dual /= w.dual.trace();
  } else if (form == WeightForm::Diagonal) {
    double sum = 0;
    for (std::size_t r = 0; r < rows.size(); ++r) sum += packed[static_cast<std::size_t>(1 + n + 81) + r];
    if (!(sum > 0)) return std::nullopt;
    for (std::size_t r = 0; r < rows.size(); ++r)
      w.row_weights.push_back(packed[static_cast<std::size_t>(1 + n + 81) + r] / sum);
  }
  return w;
}

}  // namespace scalcal
