// Exact criteria of a moment matrix M = H^T H (or sum w h h^T) of N positions for a model of P
// parameters: N^P det K, N trace K, N lambda_max K, N max K(r,r) and the thetas of the model's
// groups, with K = M^-1 inverted block by block (the connected components of M's sparsity
// pattern), so symmetric programs stay cheap.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/model.hpp"

namespace scalcal::symbolic {

// A criterion that is the largest of a few closed forms. When the closed forms hold free
// parameters, their order is unknown and the value is reported as max(c1, c2, ...).
struct ExactValue {
  std::vector<GiNaC::ex> candidates;
  bool exact = true;  // false: the candidates are floating-point values (an eigenvalue had no closed form)

  bool resolved() const;    // every candidate evaluates to a real number
  GiNaC::ex value() const;  // the largest candidate; requires resolved()
  double number() const;    // value() as a double; NaN when not resolved
  std::string str() const;  // "c" or "max(c1, c2, ...)"
};

struct ExactCriteria {
  GiNaC::ex N;
  // Every registered criterion by CriterionKind index; no candidates where there is no closed form here.
  std::array<ExactValue, kCriterionCount> values;
  ExactValue theta_bias, theta_scale, theta_nonorth, theta_cubic;  // no candidates: the model lacks the group
  std::vector<GiNaC::ex> eigenvalues;  // of M (one per eigenvalue with multiplicity) when exact
  std::vector<GiNaC::ex> K_diagonal;   // K(r, r), r = 0..P-1

  // A criterion's exact value; nullptr where it has no closed form here.
  const ExactValue* of(CriterionKind c) const {
    const ExactValue& v = values[static_cast<std::size_t>(c.index())];
    return v.candidates.empty() ? nullptr : &v;
  }
  // By the criterion's registered name ("D"), for readability where one is meant; throws
  // std::out_of_range when it has no closed form here.
  const ExactValue& at(std::string_view name) const;
};

// The paper's nine parameters in their groups (bias, scale, non-orthogonality, three each).
std::vector<ParameterGroup> paper9_groups();

// groups: the group of each of M's rows (paper9_groups() for the paper's model).
// Throws std::invalid_argument when M is singular (a block has zero determinant).
ExactCriteria exact_criteria(const GiNaC::matrix& M, const GiNaC::ex& N);
ExactCriteria exact_criteria(const GiNaC::matrix& M, const GiNaC::ex& N, const std::vector<ParameterGroup>& groups);

// The components of M's sparsity pattern (index sets, each ascending).
std::vector<std::vector<int>> blocks(const GiNaC::matrix& M);

}  // namespace scalcal::symbolic
