// The paper's iterative scalar calibration (eqs. 3-6): compensate the measurements with the
// current estimate, form the modulus residual J with m_I (norm, eq. 3) or m_II (projection on
// the nominal direction, eq. 4), solve the least-squares step (6), repeat until it is negligible.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Cholesky>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/model/design.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal {

enum class Modulus { norm, projection };

// The samples taken in one measurement position. `nominal` is the direction the bench puts the
// measured vector in (needed by the projection modulus only).
template <class Scalar>
struct PositionSamplesTpl {
  std::vector<Vec3T<Scalar>> samples;
  std::optional<Vec3T<Scalar>> nominal;
  int line = 0;                   // first line of the position in its file, for messages
  std::vector<int> sample_lines;  // the line of each sample (empty when not read from a file)

  Vec3T<Scalar> mean() const {
    Vec3T<Scalar> s = Vec3T<Scalar>::Zero();
    for (const auto& v : samples) s += v;
    return s / Scalar(static_cast<int>(samples.size()));
  }
};

template <class Scalar>
struct CalibrationOptionsTpl {
  Modulus modulus = Modulus::norm;
  Scalar magnitude = Scalar(1);  // |I| in the units of the samples
  int max_iterations = 50;
  // Each position's weight in the least squares: its number of samples (the paper's eq. 6 for
  // white noise), or 1 (a raw log's intervals are as long as the hand held still: their length
  // says nothing about their worth, and errors that differ between positions dominate there).
  bool weight_by_samples = true;
  // The update is negligible when max |dX| falls below this (X is dimensionless).
  Scalar tolerance = Scalar(1e4) * Eigen::NumTraits<Scalar>::epsilon();
};

// differences: from the log's second differences (a tumbling log's one-sample positions).
enum class NoiseSource { scatter, residuals, none, differences };

template <class Scalar>
struct CalibrationResultTpl {
  Vec9T<Scalar> X = Vec9T<Scalar>::Zero();      // (Delta / |I|, dk, gamma), eq. (5)
  Vec9T<Scalar> X_std = Vec9T<Scalar>::Zero();  // standard errors sqrt(sigma_J^2 K(r, r))
  Mat9T<Scalar> K = Mat9T<Scalar>::Zero();      // (H^T W H)^-1, W = samples per position
  Scalar noise = Scalar(0);                     // std of one sample's modulus, units of the samples
  NoiseSource noise_source = NoiseSource::none;
  Scalar residual_rms = Scalar(0);  // RMS over positions of m - |I| at the estimate, units of the samples
  int iterations = 0;
  Summary summary;  // converged, or why not (iterations, a message)
  int positions = 0;
  int samples = 0;

  Vec3T<Scalar> bias(const Scalar& magnitude) const { return X.template segment<3>(0) * magnitude; }
  Vec3T<Scalar> bias_std(const Scalar& magnitude) const { return X_std.template segment<3>(0) * magnitude; }
};

using PositionSamples = PositionSamplesTpl<double>;
using CalibrationOptions = CalibrationOptionsTpl<double>;
using CalibrationResult = CalibrationResultTpl<double>;

namespace detail {

template <class Scalar>
Scalar modulus_of(const Vec3T<Scalar>& compensated, const PositionSamplesTpl<Scalar>& p, Modulus m) {
  return m == Modulus::norm ? compensated.norm() : compensated.dot(*p.nominal);
}

}  // namespace detail

// The direction of each position as the estimator uses it in h(eta): the normalised mean
// measurement for the norm modulus (the meter's own view, immune to bench errors), the nominal
// direction for the projection modulus. Callers check the rank of these before calibrating.
template <class Scalar>
std::vector<Vec3T<Scalar>> position_directions(const std::vector<PositionSamplesTpl<Scalar>>& data, Modulus m) {
  std::vector<Vec3T<Scalar>> out;
  for (const auto& p : data) out.push_back(m == Modulus::norm ? p.mean().normalized() : p.nominal->normalized());
  return out;
}

namespace detail {

// Equal weights: the covariance of X is K (sum_i h_i h_i^T / n_i) K per unit of a sample's variance
// (each position's mean has variance sigma^2 / n_i); the result holds that, so that
// X_std = sigma_J sqrt(K(r, r)) stays true.
template <class Scalar>
Mat9T<Scalar> equal_weight_covariance(const Mat9T<Scalar>& K, const std::vector<PositionSamplesTpl<Scalar>>& data,
                                      const std::vector<Vec3T<Scalar>>& means, const Vec9T<Scalar>& X,
                                      const CalibrationOptionsTpl<Scalar>& options) {
  const MeterTpl<Scalar> meter = MeterTpl<Scalar>::from_parameters(X, options.magnitude);
  Mat9T<Scalar> middle = Mat9T<Scalar>::Zero();
  for (std::size_t i = 0; i < data.size(); ++i) {
    const Vec3T<Scalar> c = meter.compensate(means[i]);
    const Vec3T<Scalar> eta =
        options.modulus == Modulus::norm ? Vec3T<Scalar>(c.normalized()) : Vec3T<Scalar>(data[i].nominal->normalized());
    const Vec9T<Scalar> h = Paper9Model::row(eta);
    middle += h * h.transpose() / Scalar(static_cast<int>(data[i].samples.size()));
  }
  return K * middle * K;
}

// The noise: the pooled scatter of the samples about their position's mean when positions repeat,
// else from the residuals' sum of squares ss (N - 9 degrees of freedom), else none.
template <class Scalar>
void estimate_noise(CalibrationResultTpl<Scalar>& r, const std::vector<PositionSamplesTpl<Scalar>>& data,
                    const Vec9T<Scalar>& X, const CalibrationOptionsTpl<Scalar>& options, const Scalar& ss) {
  using std::sqrt;
  const Scalar M = options.magnitude;
  if (r.samples > r.positions) {
    const MeterTpl<Scalar> meter = MeterTpl<Scalar>::from_parameters(X, M);
    Scalar scatter(0);
    for (const auto& p : data) {
      std::vector<Scalar> m;
      Scalar mean(0);
      for (const auto& s : p.samples) {
        m.push_back(modulus_of(meter.compensate(s), p, options.modulus));
        mean += m.back();
      }
      mean /= Scalar(static_cast<int>(m.size()));
      for (const auto& v : m) scatter += (v - mean) * (v - mean);
    }
    r.noise = sqrt(scatter / Scalar(r.samples - r.positions));
    r.noise_source = NoiseSource::scatter;
  } else if (r.positions > kParameters) {
    r.noise = sqrt(ss / Scalar(r.positions - kParameters)) * M;
    r.noise_source = NoiseSource::residuals;
  }
}

}  // namespace detail

// Several samples of one position are averaged first and the step is weighted by their count,
// which for equal counts is eq. (6) itself. The noise is the pooled scatter of the samples about
// their position's mean when positions repeat, else it comes from the residuals (N - 9 degrees of
// freedom); with 9 single-sample positions it cannot be estimated (noise_source none, X_std 0).
// Preconditions (checked by the callers with evaluate()): rank 9, nominal set for projection.
template <class Scalar>
CalibrationResultTpl<Scalar> calibrate(const std::vector<PositionSamplesTpl<Scalar>>& data,
                                       const CalibrationOptionsTpl<Scalar>& options) {
  using std::abs;
  using std::isfinite;
  using std::sqrt;
  const Scalar M = options.magnitude;
  CalibrationResultTpl<Scalar> r;
  r.positions = static_cast<int>(data.size());
  for (const auto& p : data) r.samples += static_cast<int>(p.samples.size());

  std::vector<Vec3T<Scalar>> means;
  for (const auto& p : data) means.push_back(p.mean());

  Vec9T<Scalar> X = Vec9T<Scalar>::Zero();
  Mat9T<Scalar> info = Mat9T<Scalar>::Zero();
  std::vector<Scalar> J(data.size());
  Scalar cost(0);  // sum w J^2 at the last point residuals() saw
  auto residuals = [&](const Vec9T<Scalar>& at) {
    const MeterTpl<Scalar> meter = MeterTpl<Scalar>::from_parameters(at, M);
    Vec9T<Scalar> rhs = Vec9T<Scalar>::Zero();
    info.setZero();
    cost = Scalar(0);
    for (std::size_t i = 0; i < data.size(); ++i) {
      const Vec3T<Scalar> c = meter.compensate(means[i]);
      const Vec3T<Scalar> eta = options.modulus == Modulus::norm ? Vec3T<Scalar>(c.normalized())
                                                                 : Vec3T<Scalar>(data[i].nominal->normalized());
      J[i] = detail::modulus_of(c, data[i], options.modulus) / M - Scalar(1);
      const Scalar w = options.weight_by_samples ? Scalar(static_cast<int>(data[i].samples.size())) : Scalar(1);
      const Vec9T<Scalar> h = Paper9Model::row(eta);
      info += w * h * h.transpose();
      rhs += w * J[i] * h;
      cost += w * J[i] * J[i];
    }
    return rhs;
  };

  // Gauss-Newton on sum w J^2 with a backtracking line search: a step that does not lower the
  // residual is halved, so the iteration cannot run away from a poor start; none that lowers it
  // ends the iteration as not converged (the message says so), never a diverged estimate.
  r.summary.termination = Termination::not_converged;
  r.summary.message = "the iteration limit was reached";
  Vec9T<Scalar> rhs = residuals(X);
  for (r.iterations = 1; r.iterations <= options.max_iterations; ++r.iterations) {
    // J = m/|I| - 1 ~ h.(X_true - X): the step is the least-squares fit of the residual (6).
    const Vec9T<Scalar> dX = info.ldlt().solve(rhs);
    const Scalar before = cost;
    Scalar t(1);
    bool accepted = false;
    Vec9T<Scalar> next;
    for (int halvings = 0; halvings < 30 && !accepted; ++halvings, t /= Scalar(2)) {
      next = X + t * dX;
      bool finite = true;
      for (int k = 0; k < 9; ++k) finite = finite && isfinite(next(k));
      if (!finite) continue;
      rhs = residuals(next);
      accepted = isfinite(cost) && cost <= before;
    }
    if (!accepted) {
      rhs = residuals(X);
      if (dX.cwiseAbs().maxCoeff() < sqrt(options.tolerance)) {
        r.summary.termination = Termination::converged;  // at the rounding floor of the residual
        r.summary.message = "converged (the residual cannot be lowered further in this precision)";
      } else {
        r.summary.message =
            "no step along the Gauss-Newton direction lowers the residual (the model does not fit "
            "these data, or the start is too far)";
      }
      break;
    }
    X = next;
    if ((t * Scalar(2) * dX).cwiseAbs().maxCoeff() < options.tolerance) {
      r.summary.termination = Termination::converged;
      r.summary.message = "converged";
      break;
    }
  }
  if (r.iterations > options.max_iterations) r.iterations = options.max_iterations;
  r.summary.iterations = r.iterations;
  r.X = X;

  // Final residuals and the information matrix at the estimate.
  residuals(X);
  Eigen::LDLT<Mat9T<Scalar>> ldlt(info);
  r.K = ldlt.solve(Mat9T<Scalar>::Identity());
  if (!options.weight_by_samples) r.K = detail::equal_weight_covariance(r.K, data, means, X, options);
  Scalar ss(0);
  for (std::size_t i = 0; i < data.size(); ++i) ss += J[i] * J[i];
  r.residual_rms = sqrt(ss / Scalar(r.positions)) * M;

  detail::estimate_noise(r, data, X, options, ss);
  if (r.noise_source != NoiseSource::none) {
    const Scalar sigma_J = r.noise / M;
    for (int k = 0; k < 9; ++k) r.X_std(k) = sigma_J * sqrt(r.K(k, k));
  }
  return r;
}

extern template CalibrationResultTpl<double> calibrate(const std::vector<PositionSamplesTpl<double>>&,
                                                       const CalibrationOptionsTpl<double>&);

}  // namespace scalcal
