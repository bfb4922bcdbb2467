// calibrate --model and simulate --model: the model's meter against its own inverse, the generic
// estimator against the paper's (two implementations of eqs. 3-6), recovery of a simulated meter's
// parameters from noise-free data (truth from the meter's construction, error second order in the
// meter's size), the Monte-Carlo covariance against sigma^2 K, and the refusals.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/monte_carlo.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {

ModelKind model(const char* name) { return *parse_model(name); }

std::vector<PositionSamples> noise_free(const AnyMeter& meter, const Program& program) {
  std::vector<PositionSamples> data;
  for (const Vec3& eta : program.positions) {
    PositionSamples p;
    p.nominal = eta;
    p.samples = {meter.measure(eta), meter.measure(eta)};  // two samples: the noise is estimable (zero)
    data.push_back(p);
  }
  return data;
}

TEST(ModelCalibration, TheMeterCompensatesWhatItMeasures) {
  const AnyMeter m = reference_model_meter(model("cubic12"), 0.01);
  ASSERT_NE(m.as<CubicMeter>(), nullptr);
  ASSERT_NE(m.as<CubicMeter>()->cubic.norm(), 0.0);
  for (const Vec3& I : {Vec3(1, 0, 0), Vec3(0.3, -0.8, 0.52), Vec3(-2, 1, 4)})
    EXPECT_LT((m.compensate(m.measure(I)) - I).norm(), 1e-13 * I.norm());
}

// Each model estimates the meter its type names (numeric/model/*.hpp): the linear models eq. (2)'s, cubic12 its
// own with the quadratic output terms. A fit's meter is that type, whatever the front end asked.
TEST(ModelMeters, EachModelEstimatesItsOwnMeter) {
  for (const char* m : {"paper9", "axis6", "bias3"}) {
    const Eigen::VectorXd X = Eigen::VectorXd::Constant(model_parameters(model(m)), 1e-3);
    EXPECT_NE(model_meter(model(m), X, 1.0).as<LinearMeter>(), nullptr) << m;
    EXPECT_EQ(meter_slots(model(m)).size(), static_cast<std::size_t>(model_parameters(model(m)))) << m;
  }
  const Eigen::VectorXd X = Eigen::VectorXd::Constant(12, 1e-3);
  const AnyMeter cubic = model_meter(model("cubic12"), X, 2.0);
  ASSERT_NE(cubic.as<CubicMeter>(), nullptr);
  EXPECT_EQ(cubic.as<CubicMeter>()->cubic, Vec3::Constant(5e-4));  // c |I| = 1e-3 at |I| = 2
  // axis6's six are the linear meter's first six; bias3's its first three (by name, in the headers' order).
  const MeterSlots axis6 = meter_slots(model("axis6"));
  for (int k = 0; k < 6; ++k) EXPECT_EQ(axis6[static_cast<std::size_t>(k)].index, k);
  EXPECT_TRUE(corrects_linearly(axis6));
  EXPECT_FALSE(corrects_linearly(meter_slots(model("cubic12"))));
}

// The linear meter's axis-by-axis form is the cubic meter's at c = 0 to the last bit: the root 2r / (g + sqrt(g^2))
// is 2r / 2g = r / g exactly (sqrt of a rounded square of a double is the double; doubling is exact), so a fit
// under the linear models gives the numbers it gave when every model shared the cubic meter.
TEST(ModelMeters, TheLinearMeterIsTheCubicMeterWithoutItsTerm) {
  GaussianSource g(20261130);
  for (int t = 0; t < 200; ++t) {
    Meter m;
    for (int i = 0; i < 3; ++i) {
      m.bias(i) = 0.3 * g();
      m.scale_deviation(i) = 0.05 * g();
      for (int j = 0; j < 3; ++j)
        if (i != j) m.misalignment(i, j) = 0.02 * g();
    }
    const LinearMeter linear{m};
    const CubicMeter cubic{m, Vec3::Zero()};
    const Vec3 I(g(), g(), g());
    const Vec3 y = linear.measure(I);
    EXPECT_EQ(y, cubic.measure(I)) << t;
    EXPECT_EQ(linear.compensate(y), cubic.compensate(y)) << t;
    EXPECT_LT((linear.compensate(y) - I).norm(), 1e-13 * (1 + I.norm())) << t;
  }
}

TEST(ModelCalibration, NoiseFreeDataGiveBackTheMetersParameters) {
  const Program program = Program::octahedral(1, 1, 1);  // 26 positions: full rank for every model
  const double size = 1e-3;
  for (const char* m : {"paper9", "axis6", "bias3", "cubic12"}) {
    const ModelKind kind = model(m);
    const AnyMeter meter = reference_model_meter(kind, size);
    const Eigen::VectorXd all = meter.parameters(1.0);
    const MeterSlots slots = meter_slots(kind);
    CalibrationOptions co;
    const ModelCalibration r = calibrate_model(kind, noise_free(meter, program), co);
    ASSERT_TRUE(r.summary.converged()) << m;
    ASSERT_EQ(r.X.size(), model_parameters(kind));
    for (int k = 0; k < r.X.size(); ++k)  // the linearisation's own error is O(size^2)
      EXPECT_NEAR(r.X(k), all(slots[static_cast<std::size_t>(k)].index), 5 * size * size) << m << " " << k;
    EXPECT_LT(r.residual_rms, 1e-5) << m;
  }
}

// The generic estimator steps with the exact derivative of J, the paper's with its first-order
// rows h (eq. 6): their fixed points differ at second order in the meter's errors and residuals
// (here 5e-11), far below the standard errors.
TEST(ModelCalibration, TheGenericEstimatorAgreesWithThePapersOnPaper9) {
  const Program program = Program::octahedral(1, 1, 0);
  const Meter meter = reference_meter(2e-3);
  GaussianSource rng(5);
  const auto data = simulate_measurements(meter, program, 1e-4, 0.0, 3, rng);
  for (Modulus mod : {Modulus::norm, Modulus::projection}) {
    CalibrationOptions co;
    co.modulus = mod;
    const CalibrationResult paper = calibrate(data, co);
    const ModelCalibration generic = calibrate_model(ModelKind::paper9, data, co);
    for (int k = 0; k < 9; ++k) {
      EXPECT_NEAR(generic.X(k), paper.X(k), 1e-3 * paper.X_std(k)) << k;
      EXPECT_NEAR(generic.X_std(k), paper.X_std(k), 1e-6 * paper.X_std(k)) << k;
    }
    EXPECT_NEAR(generic.noise, paper.noise, 1e-12);
  }
}

TEST(ModelCalibration, MonteCarloCovarianceIsSigmaSquaredK) {
  for (const char* m : {"axis6", "bias3", "cubic12"}) {
    MonteCarloOptions o;
    o.program = Program::octahedral(1, 1, 1);
    o.trials = 1500;
    o.noise = 1e-4;
    o.seed = 3;
    const MonteCarloResult r = run_monte_carlo(o, {}, model(m));
    ASSERT_EQ(r.converged, o.trials) << m;
    ASSERT_EQ(static_cast<int>(r.names.size()), model_parameters(model(m)));
    for (int k = 0; k < r.truth.size(); ++k) {
      const double ratio = std::sqrt(r.empirical_cov(k, k) / r.theoretical_cov(k, k));
      EXPECT_NEAR(ratio, 1.0, 5 * r.std_sampling_error()) << m << " " << r.names[static_cast<std::size_t>(k)];
    }
    EXPECT_EQ(std::isnan(r.theta_theoretical(3)), std::string(m) != "cubic12") << m;
  }
}

using testing::run_cli;
using Json = nlohmann::json;

std::string write_axes_bench() {
  // Twelve positions along the axes of a slightly biased meter, in units of |I| = 1.
  const std::string path =
      (std::filesystem::temp_directory_path() / ("scalcal_model_axes_" + std::to_string(::getpid()) + ".csv")).string();
  std::ofstream f(path);
  f << "position,ix,iy,iz,x,y,z\n";
  int id = 0;
  for (int rep = 0; rep < 2; ++rep)
    for (int axis = 0; axis < 3; ++axis)
      for (int s : {1, -1}) {
        Vec3 e = Vec3::Zero();
        e(axis) = s;
        const Vec3 y = e + Vec3(1e-3, -2e-3, 5e-4);
        ++id;
        for (double n : {-1e-5, 1e-5})
          f << id << "," << y(0) + n << "," << y(1) - n << "," << y(2) + n << "," << e(0) << "," << e(1) << "," << e(2)
            << "\n";
      }
  return path;
}

TEST(ModelCalibrationCli, AxisPositionsIdentifyAxis6ButNotCubic12) {
  const std::string file = write_axes_bench();
  const auto ok = run_cli("calibrate --measurements " + file + " --magnitude 1 --model axis6 --json");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const Json j = Json::parse(ok.out);
  EXPECT_EQ(j["model"], "axis6");
  ASSERT_EQ(j["parameters"].size(), 6u);
  EXPECT_NEAR(j["parameters"]["bias_y"].get<double>(), -2e-3, 1e-5);  // file units (|I| = 1)
  EXPECT_NE(j["not_estimated"].get<std::string>().find("orthogonal"), std::string::npos);
  const auto cubic = run_cli("calibrate --measurements " + file + " --magnitude 1 --model cubic12");
  EXPECT_EQ(cubic.status, 2);
  EXPECT_NE(cubic.err.find("cubic_x"), std::string::npos) << cubic.err;
  EXPECT_NE(cubic.err.find(file), std::string::npos) << cubic.err;
  const auto automatic = run_cli("calibrate --measurements " + file + " --magnitude auto --model cubic12");
  EXPECT_EQ(automatic.status, 2);
  EXPECT_NE(automatic.err.find("cubic12"), std::string::npos) << automatic.err;
  // Faces only: --model auto (the default) fits axis6 and says so on stderr.
  const auto chosen = run_cli("calibrate --measurements " + file + " --magnitude 1 --json");
  ASSERT_EQ(chosen.status, 0) << chosen.err;
  EXPECT_EQ(Json::parse(chosen.out)["model"], "axis6");
  EXPECT_NE(chosen.err.find("model axis6 (auto)"), std::string::npos) << chosen.err;
  std::remove(file.c_str());
}

TEST(ModelCalibrationCli, SimulateTakesTheModel) {
  const auto r =
      run_cli("simulate --program octahedral-1-1-1 --trials 300 --noise 1e-4 --model cubic12 --modulus norm --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["model"], "cubic12");
  const Json& res = j["results"][0];
  EXPECT_EQ(res["parameters"].size(), 12u);
  EXPECT_EQ(res["parameters"][11]["name"], "cubic_z");
  EXPECT_TRUE(res["theta_theoretical"].contains("cubic"));
  const auto rank = run_cli("simulate --program octahedral-2-0-0 --trials 10 --noise 1e-4 --model cubic12");
  EXPECT_EQ(rank.status, 2);
  EXPECT_NE(rank.err.find("rank 6 of 12"), std::string::npos) << rank.err;
}

}  // namespace
}  // namespace scalcal
