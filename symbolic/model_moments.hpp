// A registered model's exact moment matrix sum_i w_i h(eta_i) h(eta_i)^T, built from a program's
// moments: the rows are the model's monomials (numeric/model's exponent tables), so a model
// registered there reaches `family --model` with no code here.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include <ginac/ginac.h>

#include "numeric/model/registry.hpp"
#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

// The exponents (a, b, c) of each row x^a y^b z^c; nullopt for a model whose row is not a list of
// monomials.
std::optional<std::vector<std::array<int, 3>>> model_exponents(ModelKind model);

// The group of each of the model's parameters.
std::vector<ParameterGroup> model_groups(ModelKind model);

// P x P, entry (r, c) = moment(e_r + e_c). Throws std::invalid_argument for a model without
// exponents.
GiNaC::matrix model_moment_matrix(ModelKind model, const MomentFunction& moment);

}  // namespace scalcal::symbolic
