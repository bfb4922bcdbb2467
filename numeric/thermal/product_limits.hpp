// The limits of a thermal model over positions and set-points (Theorem 25, proofs/thermal_product.md):
// with every parameter drifting, the row is h(eta) (x) f(tau), a product design's information matrix is
// M_sphere (x) M_interval, and the product of the two factors' optimal designs is optimal for D, A, E and
// S over all designs on sphere x [T1, T2]; the limits multiply (D: D_s^(k+1) D_1^P). With only the
// biases drifting (rows odd in eta, the others even) D and A still factor; E and S do not, and no limit
// is stated for them.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "numeric/thermal/interval_design.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal {

struct ThermalLimit {
  CriterionKind criterion = CriterionKind::D;
  double value = 0;            // the normalised limit over positions and set-points (tau's coefficients)
  double lower_bound = 0;      // no design does better (equals value where the temperature factor is proven)
  double sphere = 0;           // the base model's limit on the sphere it is built from
  IntervalDesign temperature;  // the optimal set-points' factor
  std::string form;            // how the two factors combine, e.g. "D_s^4 * D_1^9"
};

// nullopt where Theorem 25 does not determine the limit (E and S with only the biases drifting, a
// criterion with no form in information_criteria.hpp, or a bias-only model whose bias rows are not
// decoupled from the others).
std::optional<ThermalLimit> thermal_limit(CriterionKind c, const ThermalModel& model, double sphere_limit);

// Whether the drifting rows are odd in eta and the others even (what the bias-only product needs).
bool bias_rows_decoupled(const ThermalModel& model);

}  // namespace scalcal
