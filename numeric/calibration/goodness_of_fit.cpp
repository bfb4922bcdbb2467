#include "numeric/calibration/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <boost/math/distributions/chi_squared.hpp>

#include "numeric/calibration/line_list.hpp"

namespace scalcal {

std::optional<GoodnessOfFit> goodness_of_fit(const std::vector<PositionSamples>& data, const CalibrationResult& r,
                                             Modulus modulus, double M) {
  if (r.noise_source != NoiseSource::scatter || !(r.noise > 0) || r.positions <= kParameters) return std::nullopt;
  const Meter meter = Meter::from_parameters(r.X, M);
  GoodnessOfFit g;
  g.dof = r.positions - kParameters;
  for (const auto& p : data) {
    const Vec3 c = meter.compensate(p.mean());
    const double m = modulus == Modulus::norm ? c.norm() : c.dot(p.nominal->normalized());
    const double z = (m - M) * std::sqrt(static_cast<double>(p.samples.size())) / r.noise;
    g.chi_square += z * z;
    if (std::abs(z) > kDisagreeZ) g.disagreeing.emplace_back(std::abs(z), p.line);
  }
  std::sort(g.disagreeing.rbegin(), g.disagreeing.rend());
  g.p = boost::math::cdf(boost::math::complement(boost::math::chi_squared(g.dof), g.chi_square));
  return g;
}

std::string fit_warning(const GoodnessOfFit& g) {
  std::ostringstream s;
  s << std::setprecision(4) << "the fit contradicts its own noise estimate: chi-square " << g.chi_square << " for "
    << g.dof << " degrees of freedom (p = " << std::setprecision(2) << g.p
    << ") of the position residuals against the scatter within positions; ";
  if (g.disagreeing.empty()) {
    s << "no single position stands out (model misfit?)";
  } else {
    s << "positions that disagree (first line, |residual| in standard errors):" << line_list(g.disagreeing)
      << " (mislabelled positions or outliers?)";
  }
  return s.str();
}

}  // namespace scalcal
