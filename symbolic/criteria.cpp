// Block-wise exact criteria. Eigenvalues come in closed form for 1x1 blocks, for blocks
// p I + q J (all the symmetric families) and for 2x2 blocks; a larger irregular block falls
// back to floating-point eigenvalues, which is reported (ExactValue::exact = false).
#include "symbolic/criteria.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;
using GiNaC::matrix;

bool ExactValue::resolved() const {
  for (const auto& c : candidates)
    if (!GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(c)) || !GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(c)).is_real())
      return false;
  return !candidates.empty();
}

ex ExactValue::value() const {
  if (!resolved()) throw std::logic_error("ExactValue::value: candidates are not all numbers");
  std::size_t best = 0;
  double best_v = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double v = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(candidates[i])).to_double();
    if (v > best_v) best_v = v, best = i;
  }
  return candidates[best];
}

double ExactValue::number() const {
  if (!resolved()) return std::numeric_limits<double>::quiet_NaN();
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(value())).to_double();
}

namespace {

// Display form: with free parameters, numerator and denominator factored (far shorter).
ex display(const ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(e))) return e;
  try {
    const ex nd = GiNaC::normal(e).numer_denom();
    return GiNaC::factor(nd.op(0)) / GiNaC::factor(nd.op(1));
  } catch (const std::exception&) {
    return e;
  }
}

}  // namespace

std::string ExactValue::str() const {
  std::ostringstream s;
  if (resolved()) {
    s << canonical_text(value());
  } else if (candidates.size() == 1) {
    s << canonical_text(display(candidates[0]));
  } else {
    s << "max(";
    for (std::size_t i = 0; i < candidates.size(); ++i) s << (i ? ", " : "") << canonical_text(display(candidates[i]));
    s << ")";
  }
  return s.str();
}

std::vector<std::vector<int>> blocks(const matrix& M) {
  const int P = static_cast<int>(M.rows());
  std::vector<int> label(static_cast<std::size_t>(P), -1);
  int next = 0;
  for (int start = 0; start < P; ++start) {
    if (label[start] >= 0) continue;
    std::vector<int> stack{start};
    label[start] = next;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int j = 0; j < P; ++j)
        if (label[j] < 0 && !M(i, j).is_zero()) label[j] = next, stack.push_back(j);
    }
    ++next;
  }
  std::vector<std::vector<int>> out(next);
  for (int i = 0; i < P; ++i) out[label[i]].push_back(i);
  return out;
}

namespace {

// Keeps one copy of each closed form (compared exactly), in order of first appearance.
void add_distinct(std::vector<ex>& list, const ex& e) {
  for (const auto& c : list)
    if (is_zero_exact(c - e)) return;
  list.push_back(e);
}

// sqrt(r) with the square part of a positive rational r taken out (sqrt(40960) = 64 sqrt(10)),
// which GiNaC does not do; anything else as GiNaC's sqrt.
ex simplified_sqrt(const ex& r) {
  if (!GiNaC::is_a<GiNaC::numeric>(r)) return GiNaC::sqrt(r);
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(r);
  if (!q.is_rational() || !q.is_positive()) return GiNaC::sqrt(r);
  // sqrt(n/d) = sqrt(n d) / d; then n d = s^2 m with m free of squares below the trial bound.
  GiNaC::numeric m = q.numer() * q.denom(), s = 1;
  for (long p = 2; p <= 100000 && GiNaC::numeric(p * p) <= m; ++p)
    while (GiNaC::irem(m, GiNaC::numeric(p * p)).is_zero()) m = m / GiNaC::numeric(p * p), s = s * GiNaC::numeric(p);
  return s / q.denom() * GiNaC::sqrt(ex(m));
}

// Eigenvalues (with multiplicity) of a symmetric block, or empty when there is no closed form.
std::vector<ex> block_eigenvalues(const matrix& B) {
  const unsigned s = B.rows();
  if (s == 1) return {B(0, 0)};
  bool pIqJ = true;
  for (unsigned i = 0; i < s && pIqJ; ++i)
    for (unsigned j = 0; j < s && pIqJ; ++j) {
      const ex ref = i == j ? B(0, 0) : B(0, 1);
      if (!is_zero_exact(B(i, j) - ref)) pIqJ = false;
    }
  if (pIqJ) {
    std::vector<ex> ev(s - 1, canonical(B(0, 0) - B(0, 1)));
    ev.push_back(canonical(B(0, 0) + (int(s) - 1) * B(0, 1)));
    return ev;
  }
  if (s == 2) {
    const ex tr = B(0, 0) + B(1, 1);
    const ex disc = simplified_sqrt(canonical(GiNaC::pow(B(0, 0) - B(1, 1), 2) + 4 * GiNaC::pow(B(0, 1), 2)));
    return {canonical((tr - disc) / 2), canonical((tr + disc) / 2)};
  }
  return {};
}

// Floating-point eigenvalues of a block whose entries are numbers.
std::vector<ex> numeric_eigenvalues(const matrix& B) {
  const unsigned s = B.rows();
  Eigen::MatrixXd A(s, s);
  for (unsigned i = 0; i < s; ++i)
    for (unsigned j = 0; j < s; ++j) {
      const ex v = GiNaC::evalf(B(i, j));
      if (!GiNaC::is_a<GiNaC::numeric>(v))
        throw std::invalid_argument("exact_criteria: eigenvalues of a symbolic block");
      A(i, j) = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  std::vector<ex> out;
  for (unsigned i = 0; i < s; ++i) out.push_back(eig.eigenvalues()(i));
  return out;
}

}  // namespace

std::vector<ParameterGroup> paper9_groups() {
  using G = ParameterGroup;
  return {G::bias, G::bias, G::bias, G::scale, G::scale, G::scale, G::nonorth, G::nonorth, G::nonorth};
}

ExactCriteria exact_criteria(const matrix& M, const ex& N) { return exact_criteria(M, N, paper9_groups()); }

ExactCriteria exact_criteria(const matrix& M, const ex& N, const std::vector<ParameterGroup>& groups) {
  const int P = static_cast<int>(M.rows());
  if (static_cast<int>(groups.size()) != P || static_cast<int>(M.cols()) != P)
    throw std::invalid_argument("exact_criteria: M must be square with one group per row");
  ExactCriteria c;
  c.N = N;
  c.K_diagonal.assign(static_cast<std::size_t>(P), ex(0));
  ex det = 1, trace = 0;
  std::vector<ex> eig;
  bool eig_exact = true, eig_symbolic = false;
  for (const auto& idx : blocks(M)) {
    const unsigned s = idx.size();
    matrix B(s, s);
    for (unsigned i = 0; i < s; ++i)
      for (unsigned j = 0; j < s; ++j) B(i, j) = M(idx[i], idx[j]);
    const ex d = canonical(B.determinant());
    if (d.is_zero()) throw std::invalid_argument("exact_criteria: the information matrix is singular");
    det *= d;
    const matrix Binv = B.inverse();
    for (unsigned i = 0; i < s; ++i) {
      const ex k = canonical(Binv(i, i));
      c.K_diagonal[idx[i]] = k;
      trace += k;
    }
    auto ev = block_eigenvalues(B);
    if (ev.empty()) {
      eig_exact = false;
      // A block of symbols with no closed-form eigenvalues (a jig turned by a symbolic angle): E has
      // no value here, the other criteria keep theirs.
      bool numbers = true;
      for (unsigned i = 0; i < s && numbers; ++i)
        for (unsigned j = 0; j < s; ++j)
          if (!GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(B(i, j)))) numbers = false;
      if (!numbers) {
        eig_symbolic = true;
        continue;
      }
      ev = numeric_eigenvalues(B);
    }
    eig.insert(eig.end(), ev.begin(), ev.end());
  }
  c.eigenvalues = eig;
  // Each registered criterion's closed form, as its type states it (numeric/criteria/closed_form_kind.hpp); a
  // criterion that states none has none here.
  for (CriterionKind k : kCriteria) {
    ExactValue& v = c.values[static_cast<std::size_t>(k.index())];
    switch (criterion_closed_form(k)) {
      case ClosedFormKind::PowerOverDeterminant:
        v.candidates = {canonical(GiNaC::pow(N, P) / det)};
        break;
      case ClosedFormKind::TraceOfK:
        v.candidates = {canonical(N * trace)};
        break;
      case ClosedFormKind::LargestEigenvalueOfK:
        if (!eig_symbolic)
          for (const auto& l : eig) add_distinct(v.candidates, eig_exact ? canonical(N / l) : GiNaC::evalf(N / l));
        v.exact = eig_exact;
        break;
      case ClosedFormKind::LargestDiagonalOfK:
        for (int r = 0; r < P; ++r) add_distinct(v.candidates, canonical(N * c.K_diagonal[r]));
        break;
      case ClosedFormKind::None:
        break;
    }
  }
  ExactValue* theta[4] = {&c.theta_bias, &c.theta_scale, &c.theta_nonorth, &c.theta_cubic};
  for (int r = 0; r < P; ++r)
    add_distinct(theta[static_cast<int>(groups[static_cast<std::size_t>(r)])]->candidates,
                 GiNaC::sqrt(canonical(N * c.K_diagonal[r])));
  return c;
}

const ExactValue& ExactCriteria::at(std::string_view name) const {
  const auto k = parse_criterion(name);
  if (!k || !of(*k)) throw std::out_of_range("no closed form for criterion " + std::string(name));
  return *of(*k);
}

}  // namespace scalcal::symbolic
