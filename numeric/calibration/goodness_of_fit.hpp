// Does the fit agree with its own noise estimate? The residual J_i = m_i / |I| - 1 of each
// position's mean has the standard error (noise / |I|) / sqrt(n_i) by the scatter within
// positions, so sum z_i^2 with z_i = J_i / that error is chi-square with N - 9 degrees of freedom.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

struct GoodnessOfFit {
  double chi_square = 0, p = 1;
  int dof = 0;
  std::vector<std::pair<double, int>> disagreeing;  // (|z|, line of the position's first sample), worst first
};

// A p-value below this means the fit contradicts its noise estimate: mislabelled positions (two
// directions under one id), outliers, or a model that does not fit. Positions with |z| above
// kDisagreeZ are named.
inline constexpr double kFitRejectP = 1e-3;
inline constexpr double kDisagreeZ = 3;

// Only defined when the noise comes from repeated samples and N > 9 (otherwise the residuals are
// the noise estimate, or there are none): std::nullopt then.
std::optional<GoodnessOfFit> goodness_of_fit(const std::vector<PositionSamples>& data, const CalibrationResult& r,
                                             Modulus modulus, double magnitude);

// "the fit contradicts its own noise estimate: chi-square ... positions that disagree: line 12 (41.2), ..."
std::string fit_warning(const GoodnessOfFit& g);

}  // namespace scalcal
