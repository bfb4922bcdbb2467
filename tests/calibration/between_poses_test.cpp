// The error model of a still-pose calibration (numeric/calibration/between_poses.hpp): REML recovers
// a between-pose variance it is given (simulated, the truth known), and on the real logs of data/ a
// 95 % interval for a held-out pose's corrected modulus covers it about 95 % of the time (leave one
// position out: the fit without it predicts it; the interval is the parameters' error at its
// direction and the noise and scatter of one pose, with Student's t at the fit's degrees of freedom,
// since the variances are estimated; a fit with too few for the error model (under 5) takes the
// scatter of its residuals instead).
#include <cmath>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "commands/calibration/calibrate.hpp"
#include "numeric/calibration/between_poses.hpp"
#include "numeric/calibration/tumbling.hpp"

namespace scalcal {
namespace {

TEST(BetweenPoses, RemlRecoversTheScatterBetweenPoses) {
  // A linear model J = H d + e with e of variance s_b^2 + s_w^2 / n_k: the mean of REML's s_b^2 over
  // 400 draws is within 5 % of the truth (REML's variance estimate is unbiased to first order).
  std::mt19937_64 engine(3);
  std::normal_distribution<double> normal;
  const int n = 40, P = 9;
  const double between = 4e-8, within = 1e-6;  // the Xsens log's orders: 2e-4 and 1e-3 of |I|
  std::vector<Eigen::VectorXd> rows;
  std::vector<double> samples, weights;
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd h(P);
    for (int p = 0; p < P; ++p) h(p) = normal(engine);
    rows.push_back(h);
    samples.push_back(50 + 20 * (k % 7));
    weights.push_back(1);
  }
  double sum = 0;
  const int draws = 400;
  for (int d = 0; d < draws; ++d) {
    std::vector<double> J;
    for (int k = 0; k < n; ++k)
      J.push_back(std::sqrt(between + within / samples[static_cast<std::size_t>(k)]) * normal(engine));
    const BetweenPoses b = between_poses(rows, J, samples, weights, within);
    ASSERT_TRUE(b.converged);
    sum += b.between;
  }
  EXPECT_NEAR(sum / draws, between, 0.05 * between);
}

std::string shared_log(const std::string& name) {
  for (const auto& dir : {std::filesystem::path(SCALCAL_SOURCE_DIR) / "data",
                          std::filesystem::path(SCALCAL_SOURCE_DIR).parent_path() / "shared" / "data"})
    if (std::filesystem::exists(dir / name)) return (dir / name).string();
  return "";
}

struct Log {
  const char* name;
  const char* file;
  const char* magnitude;
  double rate;
};

class HeldOutPose : public testing::TestWithParam<Log> {};

TEST_P(HeldOutPose, NinetyFivePercentIntervalsCoverAboutNinetyFivePercent) {
  const Log& log = GetParam();
  const std::string path = shared_log(log.file);
  if (path.empty()) GTEST_SKIP() << log.file << " is in neither data/ nor ../shared/data";
  commands::CalibrateRequest q;
  q.file = path;
  q.magnitude = commands::magnitude_value(log.magnitude);
  q.rate = log.rate;
  q.suggest = 0;
  const commands::CalibrationInput in = commands::read_calibration_input(q);
  const commands::CalibrateResult all = commands::calibrate(q, in);
  ASSERT_TRUE(all.converged());
  AnyUnitsOptions o;
  o.magnitude = all.fit.magnitude;
  o.magnitude_auto = !q.magnitude;
  o.weight_by_samples = all.weight_by_samples;
  o.model = all.model;
  int covered = 0, held = 0;
  for (std::size_t k = 0; k < in.data.size(); ++k) {
    std::vector<PositionSamples> rest = in.data;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
    const AnyUnitsCalibration f = calibrate_any_units(log.name, rest, o);
    if (!f.estimate.summary.converged() || f.dof < 1) continue;
    const Vec3 c = f.correction.apply(in.data[k].mean());
    const double residual = c.norm() / f.magnitude - 1;
    const Eigen::VectorXd h = model_rows(f.model, {c.normalized()})[0];
    const double n = static_cast<double>(in.data[k].samples.size());
    const double pose =
        f.model_std.size()
            ? (f.between_std * f.between_std + f.within_std * f.within_std / n) / (f.magnitude * f.magnitude)
            : std::pow(f.estimate.residual_rms / f.magnitude, 2) * static_cast<double>(rest.size()) / f.dof;
    const double sd = std::sqrt(h.dot(f.covariance * h) + pose);
    const double t = boost::math::quantile(boost::math::students_t(f.dof), 0.975);
    covered += std::abs(residual) <= t * sd;
    ++held;
  }
  ASSERT_GE(held, static_cast<int>(in.data.size()) - 1);
  const double coverage = static_cast<double>(covered) / held;
  RecordProperty("coverage", std::to_string(coverage));
  RecordProperty("positions", std::to_string(held));
  std::printf("%s: %d of %d held-out poses within their 95 %% interval (%.3f)\n", log.name, covered, held, coverage);
  // Intervals that cover 95 % give a count of covered poses that is Binomial(held, 0.95): fail when so
  // few covered poses would happen less than 1 time in 100 (with 12 poses: 8 or fewer; with 38: 31 or
  // fewer). The NilsPod session gives 9 of 12 (probability 0.02): axis6's unmodelled non-orthogonality
  // (residuals 5.7 x the noise) is larger than 6 degrees of freedom estimate well (docs/calibrate.md).
  const double p_as_few = boost::math::cdf(boost::math::binomial(held, 0.95), covered);
  RecordProperty("probability_as_few", std::to_string(p_as_few));
  EXPECT_GE(p_as_few, 0.01) << log.name << ": " << covered << " of " << held;
}

INSTANTIATE_TEST_SUITE_P(Logs, HeldOutPose,
                         testing::Values(Log{"xsens", "xsens_acc.txt", "9.81744", 0},
                                         Log{"mpu6050", "mpu6050_acc.csv", "9.80665", 100},
                                         Log{"nilspod", "nilspod_ferraris_acc.csv", "9.81", 102.4}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace scalcal
