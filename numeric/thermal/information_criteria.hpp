// The paper's four criteria on a normalised information matrix Mbar = H^T H / N of any size (a thermal
// model's size is known only at run time): D = 1/det Mbar (= N^P det K), A = tr Mbar^-1 (= N tr K),
// E = 1/lambda_min(Mbar), S = max_r (Mbar^-1)_rr. Written here again because the registered criteria are
// templates on a model of fixed size; tests/thermal checks the two agree on the registered models.
#pragma once
#include <optional>

#include <Eigen/Core>

#include "numeric/criteria/registry.hpp"

namespace scalcal {

// nullopt for a criterion with no form here (a fifth criterion); +inf for a singular Mbar (smallest
// eigenvalue below 1e-12 of the largest).
std::optional<double> information_criterion(CriterionKind c, const Eigen::MatrixXd& mbar);

}  // namespace scalcal
