// calibrate --instrument gyro end to end through the CLI: each method's rehearsal (simulate
// --instrument gyro, its truth file) calibrated back within 4 standard errors of its truth (the
// coverage over many seeds is truth_test.cpp's), the per-segment rate column agreeing with one rate,
// the file read by correct and export, and the options refused where they do not belong.
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/export_text.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;

std::string path(const std::string& name) { return (scratch_dir() / name).string(); }

Json run_json(const std::string& args) {
  const CliResult r = run_cli(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r.status == 0 ? Json::parse(r.out) : Json();
}

// The paper's nine against the truth file: bias (raw), scale as the gain (raw per physical), gamma.
void expect_scalar_truth(const Json& c, const Json& truth) {
  const char* axes = "xyz";
  for (int k = 0; k < 3; ++k) {
    const std::string b = std::string("bias_") + axes[k];
    EXPECT_NEAR(c["parameters"][b].get<double>(), truth["bias"][k].get<double>(),
                4 * c["standard_error"][b].get<double>())
        << b;
    EXPECT_NEAR(c["gain"][k].get<double>(), truth["scale"][k].get<double>(), 4 * c["gain_std"][k].get<double>()) << k;
  }
  const char* pairs[3] = {"nonorth_xy", "nonorth_yz", "nonorth_zx"};
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(c["nonorthogonality"][k].get<double>(), truth["nonorthogonality"][k].get<double>(),
                4 * c["standard_error"][pairs[k]].get<double>())
        << pairs[k];
}

// The first n rows of a raw log and of correct's output for it: (raw, corrected) vectors.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> raw_and_corrected(const std::string& log,
                                                                           const std::string& corrected, int n) {
  std::istringstream rows(corrected), raw(slurp(log));
  std::string line, raw_line;
  std::getline(rows, line);
  std::getline(raw, raw_line);
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
  for (int i = 0; i < n && std::getline(rows, line) && std::getline(raw, raw_line); ++i) {
    double v[4], r[4];
    char comma;
    std::istringstream a(line), b(raw_line);
    a >> v[0] >> comma >> v[1] >> comma >> v[2] >> comma >> v[3];
    b >> r[0] >> comma >> r[1] >> comma >> r[2] >> comma >> r[3];
    out.push_back({Eigen::Vector3d(r[1], r[2], r[3]), Eigen::Vector3d(v[1], v[2], v[3])});
  }
  return out;
}

TEST(GyroCalibrateCli, RateTableBackToItsTruth) {
  const std::string log = path("cal_rt.csv"), truth = path("cal_rt_truth.json"), cal = path("cal_rt.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --dwell 6 --log " + log +
                    " --truth " + truth)
                .status,
            0);
  const Json c = run_json("calibrate --instrument gyro --measurements " + log + " --magnitude 1 --json --out " + cal);
  EXPECT_EQ(c["instrument"], "gyro");
  EXPECT_EQ(c["method"], "rate_table");
  EXPECT_EQ(c["model"], "paper9");
  EXPECT_EQ(c["segments"].size(), 12u);
  expect_scalar_truth(c, Json::parse(slurp(truth)));
  // The table's signed rate per row: each segment's median |rate| is 1, the same fit.
  const Json col = run_json("calibrate --instrument gyro --measurements " + log + " --magnitude column:rate --json");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(col["offset"][k].get<double>(), c["offset"][k].get<double>(), 1e-12);
  // correct and export read the file; imu_tk's T K (X - B) is correct's vector.
  const CliResult corrected = run_cli("correct --calibration " + cal + " --measurements " + log + " --out -");
  ASSERT_EQ(corrected.status, 0) << corrected.err;
  EXPECT_EQ(corrected.out.substr(0, corrected.out.find('\n')), "t,x,y,z,modulus");
  const CliResult imu_tk = run_cli("export " + cal + " --format imu_tk");
  ASSERT_EQ(imu_tk.status, 0) << imu_tk.err;
  std::istringstream t(imu_tk.out);
  double n[21];
  for (double& x : n) t >> x;
  ASSERT_TRUE(t);
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> T(n), K(n + 9);
  const Eigen::Vector3d B(n[18], n[19], n[20]);
  const auto rows = raw_and_corrected(log, corrected.out, 200);
  ASSERT_EQ(rows.size(), 200u);
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_LT((T * K * (rows[i].first - B) - rows[i].second).norm(), 1e-12) << "row " << i;
}

// A lone rest is not grouped as a rest (rests are two or more equal outputs) and read as a turn at the
// table's rate: the offsets came out 0.21 rad/s against a true 0.005, exit 0 (found by the C library's
// rate-table comparison, embedded/tests/compare_cli.py). The log is refused naming the rest's line; with no
// rest at all it is fitted from its ellipsoid start, back to its truth.
TEST(GyroCalibrateCli, ALoneRestIsNotTakenForATurn) {
  const std::string log = path("lone_rt.csv"), truth = path("lone_rt_truth.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --magnitude 3.14159 --noise 1e-3 "
                    "--dwell 10 --seed 1 --log " +
                    log + " --truth " + truth)
                .status,
            0);
  // Rows whose table rate (the fifth column) is 0 are the rests: keep only the first one.
  std::istringstream in(slurp(log));
  std::string head, line;
  std::getline(in, head);
  std::string one = head + "\n", none = head + "\n";
  bool moved = false;
  while (std::getline(in, line)) {
    const bool rest = std::stod(line.substr(line.rfind(',') + 1)) == 0;
    moved = moved || !rest;
    if (!rest || !moved) one += line + "\n";
    if (!rest) none += line + "\n";
  }
  const std::string with_one = write_file("lone_one.csv", one), with_none = write_file("lone_none.csv", none);
  const CliResult r = run_cli("calibrate --instrument gyro --measurements " + with_one + " --magnitude 3.14159");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the table at rest, not turning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("record a rest between segments"), std::string::npos) << r.err;
  const Json c = run_json("calibrate --instrument gyro --measurements " + with_none + " --magnitude 3.14159 --json");
  EXPECT_EQ(c["rests"].size(), 0u);
  expect_scalar_truth(c, Json::parse(slurp(truth)));
}

TEST(GyroCalibrateCli, KnownTurnsBackToTheirTruth) {
  const std::string log = path("cal_kt.csv"), truth = path("cal_kt_truth.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --turn-angle 360 --log " + log +
                    " --truth " + truth)
                .status,
            0);
  const Json c = run_json("calibrate --instrument gyro --measurements " + log + " --turn-angle 360 --json");
  EXPECT_EQ(c["method"], "known_turns");
  EXPECT_EQ(c["turns"].size(), 12u);
  EXPECT_EQ(c["units"]["physical"], "rad/s");
  expect_scalar_truth(c, Json::parse(slurp(truth)));
}

TEST(GyroCalibrateCli, HandRotationsBackToTheirTruth) {
  const std::string log = path("cal_hg.csv"), acc = path("cal_hacc.csv"), truth = path("cal_hg_truth.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program octahedral-1-1-1 --noise 1e-3 --dwell 3 --accelerometer " +
                    acc + " --log " + log + " --truth " + truth)
                .status,
            0);
  const Json c = run_json("calibrate --instrument gyro --measurements " + log + " --accelerometer " + acc +
                          " --accelerometer-magnitude 9.80665 --json");
  const Json t = Json::parse(slurp(truth));
  EXPECT_EQ(c["method"], "hand_rotations");
  EXPECT_EQ(c["poses"].size(), 26u);
  EXPECT_TRUE(c["accelerometer"].is_object());
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(c["matrix"][a][b].get<double>(), t["matrix"][a][b].get<double>(),
                  4 * c["matrix_std"][a][b].get<double>())
          << a << b;
    EXPECT_NEAR(c["offset"][a].get<double>(), t["offset"][a].get<double>(), 4 * c["offset_std"][a].get<double>());
  }
}

// A gyro's exports applied as their targets apply them give correct's vectors: OpenVINS's kalibr model
// w = R_IMUtoGYRO^T Tw^-1 (w_m - b_g) with the offset as its initial bias; PX4's and ArduPilot's offsets
// (w_m - offset) on an offsets-only calibration (bias3, whose common gain they drop and say so).
TEST(GyroCalibrateCli, ExportsAppliedTheirTargetsWay) {
  const std::string log = path("cal_export.csv"), cal = path("cal_export.json"), cal3 = path("cal_export3.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --dwell 6 --log " + log).status,
            0);
  const std::string base = "calibrate --instrument gyro --measurements " + log + " --magnitude 1 --units rad/s,rad/s";
  ASSERT_EQ(run_cli(base + " --out " + cal).status, 0);
  ASSERT_EQ(run_cli(base + " --model bias3 --out " + cal3).status, 0);
  const CliResult corrected = run_cli("correct --calibration " + cal + " --measurements " + log + " --out -");
  const CliResult corrected3 = run_cli("correct --calibration " + cal3 + " --measurements " + log + " --out -");
  ASSERT_EQ(corrected.status, 0) << corrected.err;
  ASSERT_EQ(corrected3.status, 0) << corrected3.err;

  const CliResult k = run_cli("export " + cal + " --format kalibr");
  ASSERT_EQ(k.status, 0) << k.err;
  const auto tw = numbers_after(k.out, "  Tw:", 9), rg = numbers_after(k.out, "R_IMUtoGYRO:", 9),
             bg = numbers_after(k.out, "initial bias:", 3);
  ASSERT_EQ(tw.size() + rg.size() + bg.size(), 21u) << k.out;
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Tw(tw.data()), R(rg.data());
  const Eigen::Vector3d b(bg[0], bg[1], bg[2]);
  EXPECT_EQ(Tw(0, 1), 0);
  EXPECT_LT((R * R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  for (const auto& [raw, c] : raw_and_corrected(log, corrected.out, 300)) {
    const Eigen::Vector3d w = R.transpose() * Eigen::Matrix3d(Tw).triangularView<Eigen::Lower>().solve(raw - b);
    ASSERT_LT((w - c).norm(), 1e-12 * c.norm()) << raw.transpose();
  }

  const CliResult px4 = run_cli("export " + cal3 + " --format px4");
  const CliResult ap = run_cli("export " + cal3 + " --format ardupilot");
  ASSERT_EQ(px4.status, 0) << px4.err;
  ASSERT_EQ(ap.status, 0) << ap.err;
  // bias3 on a rate table keeps one common gain g (the known rate fixes the scale): the targets drop it
  // and say so; raw minus their offsets (9 digits printed), times g, is correct's vector to 1e-9 rad/s.
  EXPECT_NE(px4.err.find("cannot carry a gyroscope's scale factors"), std::string::npos) << px4.err;
  const double g = Json::parse(slurp(cal3))["matrix"][0][0].get<double>();
  const auto p = parameters(px4.out), a = parameters(ap.out);
  const Eigen::Vector3d o_px4(p.at("CAL_GYRO0_XOFF"), p.at("CAL_GYRO0_YOFF"), p.at("CAL_GYRO0_ZOFF"));
  const Eigen::Vector3d o_ap(a.at("INS_GYROFFS_X"), a.at("INS_GYROFFS_Y"), a.at("INS_GYROFFS_Z"));
  for (const auto& [raw, c] : raw_and_corrected(log, corrected3.out, 300)) {
    ASSERT_LT((g * (raw - o_px4) - c).norm(), 1e-9) << raw.transpose();
    ASSERT_LT((g * (raw - o_ap) - c).norm(), 1e-9) << raw.transpose();
  }
}

// The Earth's rate along a tilted table's axis (--table-axis): Omega (0, cos phi, sin phi) . a. An axis
// tilted 30 degrees from up toward north at latitude 15 sees Omega (sin 30 cos 15 + cos 30 sin 15) =
// Omega sin 45, a vertical axis at latitude 45 the same; an axis pointing east sees none of it.
TEST(GyroCalibrateCli, TheEarthsRateAlongATiltedTableAxis) {
  const std::string log = path("cal_earth.csv"), truth = path("cal_earth_truth.json");
  ASSERT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-4 --dwell 6 --latitude 45 --log " +
                    log + " --truth " + truth)
                .status,
            0);
  const std::string base = "calibrate --instrument gyro --measurements " + log + " --magnitude column:rate --json";
  const Json vertical = run_json(base + " --latitude 45");
  const Json tilted = run_json(base + " --latitude 15 --table-axis 0,0.5,0.8660254037844386");
  const Json east = run_json(base + " --latitude 45 --table-axis 2,0,0");
  const Json none = run_json(base);
  expect_scalar_truth(vertical, Json::parse(slurp(truth)));
  for (const char* key : {"offset", "gain", "nonorthogonality"})
    for (int k = 0; k < 3; ++k) {
      const double v = vertical[key][k].get<double>();
      EXPECT_NEAR(tilted[key][k].get<double>(), v, 1e-9 * std::max(1.0, std::abs(v))) << key << k;
      EXPECT_EQ(east[key][k].get<double>(), none[key][k].get<double>()) << key << k;
    }
  // Left out, the Earth's rate (7.3e-5 against the table's 1, 0.73 of the noise) stays in the residuals:
  // the scale factors' residual-based errors are 2.9 times those with it modelled.
  EXPECT_GT(none["standard_error"]["scale_x"].get<double>(), 2 * vertical["standard_error"]["scale_x"].get<double>());
  const CliResult zero = run_cli(base + " --latitude 45 --table-axis 0,0,0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("--table-axis"), std::string::npos) << zero.err;
  EXPECT_EQ(run_cli(base + " --latitude 45 --table-axis 1,2").status, 2);
  const CliResult alone = run_cli(base + " --table-axis 0,0,1");
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find("needs --latitude"), std::string::npos) << alone.err;
}

TEST(GyroCalibrateCli, OptionsWhereTheyBelong) {
  const std::string log = path("cal_rt.csv");
  const CliResult none = run_cli("calibrate --instrument gyro --measurements data.csv");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("say how the gyro was turned"), std::string::npos) << none.err;
  const CliResult accel = run_cli("calibrate --measurements x.csv --magnitude 1 --turn-angle 360");
  EXPECT_EQ(accel.status, 2);
  EXPECT_NE(accel.err.find("--turn-angle belongs to --instrument gyro"), std::string::npos) << accel.err;
  EXPECT_EQ(run_cli("calibrate --measurements x.csv --magnitude column:rate").status, 2);
  EXPECT_EQ(run_cli("calibrate --measurements x.csv").status, 2);
  EXPECT_EQ(run_cli("calibrate --instrument gyro --measurements x.csv --magnitude 1 --turn-angle 360").status, 2);
  EXPECT_EQ(run_cli("calibrate --instrument gyro --measurements x.csv --accelerometer a.csv").status, 2);
  const CliResult region = run_cli("calibrate --instrument gyro --measurements x.csv --magnitude 1 --region cap:40");
  EXPECT_EQ(region.status, 2);
  EXPECT_NE(region.err.find("--region is an accelerometer's option"), std::string::npos) << region.err;
}

}  // namespace
}  // namespace scalcal::testing
