#include "numeric/calibration/any_units.hpp"

#include <algorithm>
#include <cmath>

#include "numeric/calibration/data_checks.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

// Within this of the magnitude (median over positions) the data are in the field's units.
constexpr double kInUnits = 0.1;

double median_modulus_ratio(const std::vector<PositionSamples>& data, double magnitude) {
  std::vector<double> r;
  for (const auto& p : data) r.push_back(p.mean().norm() / magnitude);
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
  return r[r.size() / 2];
}

}  // namespace

AnyUnitsCalibration calibrate_any_units(const std::string& file, const std::vector<PositionSamples>& data,
                                        const AnyUnitsOptions& options) {
  AnyUnitsCalibration out;
  out.magnitude = options.magnitude_auto ? 1.0 : options.magnitude;
  const double M = out.magnitude;
  if (data.size() < static_cast<std::size_t>(kParameters)) check_calibration_data(file, data, options.modulus, M);  // throws
  const double ratio = median_modulus_ratio(data, M);
  out.started = options.magnitude_auto || std::abs(ratio - 1) > kInUnits;
  std::vector<PositionSamples> y = data;
  if (out.started) {
    if (options.modulus == Modulus::projection)
      throw InputError(file, 0,
                       "the measured modulus is " + std::to_string(ratio) +
                           " times --magnitude; the projection modulus needs data in the field's units (use the norm "
                           "modulus, which starts from an ellipsoid fit in any units)");
    std::vector<Vec3> means;
    for (const auto& p : data) means.push_back(p.mean());
    const auto start = fit_ellipsoid(means, M);
    if (!start)
      throw InputError(file, 0,
                       "no ellipsoid passes near the " + std::to_string(data.size()) +
                           " positions' means: they are too few or too flat for a start in any units");
    out.start = *start;
    for (auto& p : y)
      for (auto& s : p.samples) s = out.start.apply(s);
  }
  check_calibration_data(file, y, options.modulus, M);
  CalibrationOptions co;
  co.modulus = options.modulus;
  co.magnitude = M;
  co.weight_by_samples = options.weight_by_samples;
  out.estimate = calibrate(y, co);
  const CalibrationResult& r = out.estimate;
  const Meter meter = Meter::from_parameters(r.X, M);
  const FullCorrection second = correction_of(meter);
  const bool have_std = r.noise_source != NoiseSource::none;
  if (!out.started) {
    out.correction = second;
    out.scale_deviation = r.X.segment<3>(3);
    if (have_std) out.bias_std = r.bias_std(M);
  } else {
    // physical = G^-1 (y - Delta), y = T (raw - o): matrix G^-1 T, offset o + T^-1 Delta.
    const Mat3 T_inverse = out.start.matrix.inverse();
    const auto canonical = canonical_correction(second.matrix * out.start.matrix, out.start.offset + T_inverse * meter.bias);
    if (!canonical) throw InputError(file, 0, "the fitted correction is degenerate (two sensor axes nearly parallel)");
    out.correction = *canonical;
    out.nominal_gain = std::cbrt(out.correction.scale.prod());
    out.scale_deviation = out.correction.scale / out.nominal_gain - Vec3::Ones();
    if (have_std) {  // first order: the start is a fixed map, the estimate's covariance goes through it
      const double sigma = r.noise / M;
      const Mat3 cov = sigma * sigma * M * M * r.K.topLeftCorner<3, 3>();
      out.bias_std = (T_inverse * cov * T_inverse.transpose()).diagonal().cwiseSqrt();
    }
  }
  if (have_std) {
    const double sigma = r.noise / M;
    Mat3 cov = sigma * sigma * r.K.block<3, 3>(3, 3);
    if (out.started) {  // relative to their geometric mean: the common scale is the nominal gain's
      const Mat3 P = Mat3::Identity() - Mat3::Constant(1.0 / 3);
      cov = P * cov * P.transpose();
    }
    out.scale_deviation_std = cov.diagonal().cwiseSqrt();
    out.nonorthogonality_std = r.X_std.segment<3>(6);
  }
  // The program measured, and each position's residual against the residuals' own scale (the
  // weighted least squares' information matrix for the leverages, whatever the weights).
  const int n = static_cast<int>(data.size());
  std::vector<double> J, w;
  Mat9 info = Mat9::Zero();
  double weighted = 0;
  for (const auto& p : y) {
    const Vec3 c = meter.compensate(p.mean());
    out.directions.push_back(c.normalized());
    J.push_back((options.modulus == Modulus::norm ? c.norm() : c.dot(*p.nominal)) / M - 1);
    w.push_back(options.weight_by_samples ? static_cast<double>(p.samples.size()) : 1.0);
    const Vec9 h = Paper9Model::row(out.directions.back());
    info += w.back() * h * h.transpose();
    weighted += w.back() * J.back() * J.back();
  }
  const Mat9 K = info.ldlt().solve(Mat9::Identity());
  out.have_achieved = n > kParameters;
  const double s = out.have_achieved ? std::sqrt(weighted / (n - kParameters)) : 0;
  if (out.have_achieved) out.achieved_std = s * K.diagonal().cwiseSqrt();
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec9 h = Paper9Model::row(out.directions[k]);
    const double leverage = std::min(w[k] * h.dot(K * h), 1.0 - 1e-12);
    PositionResidual pr{data[k].line, J[k], 0.0};
    if (s > 0) pr.standardised = J[k] * std::sqrt(w[k]) / (s * std::sqrt(1 - leverage));
    out.residuals.push_back(pr);
  }
  return out;
}

}  // namespace scalcal
