// What makes bench data unusable for the scalar calibration, reported before the estimator runs:
// too few positions, a modulus far from the stated magnitude (wrong units), positions that leave
// parameters unidentifiable or determine them only with an ill-conditioned H.
#pragma once
#include <string>
#include <vector>

#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

// Throws InputError(file, 0, reason) naming what is wrong and, for a rank-deficient set of
// positions, the parameters it cannot identify.
void check_calibration_data(const std::string& file, const std::vector<PositionSamples>& data, Modulus modulus,
                            double magnitude);

}  // namespace scalcal
