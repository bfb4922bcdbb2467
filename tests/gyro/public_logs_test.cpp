// The gyro columns of the public logs against the independent SciPy fit of
// experiments/docs/gyro_fit.py (its output gyro_fit.json): the Xsens pair and the MPU-6050 log by
// hand rotations, imucal's Ferraris session by known turns. The fit there integrates with IMU-TK's
// RK4 (here the exponential map), finds its own poses and calibrates its own accelerometer (T upper
// triangular: its frame differs from scalcal's by a rotation, undone before comparing). A log found
// neither in data/, ../shared/data/ nor SCALCAL_REAL_DATA is skipped.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <Eigen/SVD>
#include <nlohmann/json.hpp>

#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/gyro/gravity_poses.hpp"
#include "numeric/gyro/hand_rotations.hpp"
#include "numeric/gyro/known_modulus.hpp"
#include "numeric/gyro/rate_segments.hpp"
#include "tests/gyro/accelerometer_poses.hpp"

namespace scalcal::gyro {
namespace {

std::string find_log(const std::string& name) {
  std::vector<std::string> dirs = {std::string(SCALCAL_SOURCE_DIR) + "/data/",
                                   std::string(SCALCAL_SOURCE_DIR) + "/../shared/data/"};
  if (const char* env = std::getenv("SCALCAL_REAL_DATA")) dirs.push_back(std::string(env) + "/");
  for (const auto& d : dirs)
    if (std::filesystem::exists(d + name)) return d + name;
  return "";
}

nlohmann::json reference(const std::string& log) {
  std::ifstream in(std::string(SCALCAL_SOURCE_DIR) + "/experiments/docs/gyro_fit.json");
  return nlohmann::json::parse(in).at(log);
}

Mat3 matrix_of(const nlohmann::json& rows) {
  Mat3 m;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) m(a, b) = rows[a][b].get<double>();
  return m;
}

void compare_hand(const std::string& log, const std::string& acc_name, const std::string& gyro_name, double rate,
                  double g, const char* acc_model) {
  const std::string acc_file = find_log(acc_name), gyro_file = find_log(gyro_name);
  if (acc_file.empty() || gyro_file.empty()) GTEST_SKIP() << gyro_name << " not found";
  const RawLog acc = read_raw_log(acc_file, LogFormat::automatic, rate),
               gyro = read_raw_log(gyro_file, LogFormat::automatic, rate);
  const testing::AccelerometerPoses ap = testing::accelerometer_poses(acc, gyro, g, acc_model);
  const AnyUnitsCalibration& a = ap.accelerometer;
  const HandRotationCalibration c = calibrate_hand_rotations(gyro, ap.poses);
  const IntervalDetection& d = ap.detection;
  const nlohmann::json ref = reference(log);
  ASSERT_EQ(ref.at("poses").get<int>(), static_cast<int>(d.intervals.size()));
  // The reference's accelerometer frame to ours: the rotation nearest C_ours T_ref^-1.
  const Mat3 M = a.correction.matrix * matrix_of(ref.at("acc_matrix")).inverse();
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Mat3 C_ref = svd.matrixU() * svd.matrixV().transpose() * matrix_of(ref.at("matrix"));
  for (int k = 0; k < 12; ++k) {
    const double mine = k < 9 ? c.matrix(k / 3, k % 3) : c.offset(k - 9);
    const double theirs = k < 9 ? C_ref(k / 3, k % 3) : ref.at("offset")[k - 9].get<double>();
    const double se = c.standard_error(k);
    EXPECT_NEAR(mine, theirs, 0.1 * se) << log << " parameter " << k;
    EXPECT_NEAR(se, ref.at("standard_error")[k].get<double>(), 0.05 * se) << log << " standard error " << k;
  }
  EXPECT_NEAR(c.misfit.angle_rms * 180 / M_PI, ref.at("misfit_rms_deg").get<double>(), 0.005);
}

TEST(PublicLogs, XsensHandRotations) { compare_hand("xsens", "xsens_acc.txt", "xsens_gyro.txt", 0, 9.81744, "paper9"); }

TEST(PublicLogs, Mpu6050HandRotations) {
  compare_hand("mpu6050", "mpu6050_acc.csv", "mpu6050_gyro.csv", 100, 9.80665, "axis6");
}

TEST(PublicLogs, FerrarisKnownTurns) {
  const std::string file = find_log("nilspod_ferraris_gyro.csv");
  if (file.empty()) GTEST_SKIP() << "nilspod_ferraris_gyro.csv not found";
  const RawLog log = read_raw_log(file, LogFormat::automatic, 102.4);
  const RateLogSegments s = segment_rate_log(log);
  Vec3 rest = Vec3::Zero();
  for (const auto& r : s.rests) rest += r.mean;
  rest /= static_cast<double>(s.rests.size());
  const auto turns = largest_turns(turns_between_rests(log, s), rest);
  ASSERT_EQ(turns.size(), 3u);
  std::string reason;
  const auto c = calibrate_known_moduli_auto(file, turn_items(turns, {2 * M_PI}, 0.05, 1 / 102.4), s.rests, reason);
  EXPECT_EQ(model_name(c.model), "axis6") << reason;
  const nlohmann::json ref = reference("nilspod_ferraris");
  EXPECT_EQ(ref.at("rests").get<int>(), static_cast<int>(s.rests.size()));
  for (int k = 0; k < 3; ++k) {
    // The offset: the rests' weighted mean there, fitted here with the turns (which carry no
    // information on it at zero degrees of freedom): equal to rounding.
    EXPECT_NEAR(c.parameters(k), ref.at("offset")[k].get<double>(), 1e-9);
    EXPECT_NEAR(c.parameters(3 + k), ref.at("gain")[k].get<double>(), 1e-7 * c.parameters(3 + k));
  }
}

}  // namespace
}  // namespace scalcal::gyro
