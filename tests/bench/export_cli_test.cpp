// scalcal export round trips: each target's file is read here the way that tool reads it and applied
// by that tool's own formula (written out below from its source: PX4's Accelerometer::Correct and
// Magnetometer::Correct, ArduPilot's _rotate_and_correct_accel and AP_Compass_Backend::correct_field,
// IMU-TK's CalibratedTriad::unbiasNormalize, OpenVINS's Propagator (a = R_ACCtoIMU Ta^-1 (a_m - b)),
// MATLAB's magcal), to the raw rows of a rehearsal log in the target's units, and compared with
// `scalcal correct` on the same rows, converted to the target's units:
//   json, magcal, imu_tk (17 digits)          the same vectors to 1e-12 relative
//   kalibr                                    the same vectors to 1e-12 (its rotation R_IMUtoACC is in
//                                             the file: no part of the correction is lost)
//   px4, ardupilot accel (9 digits, float32)  correct's vectors without the dropped off-diagonal
//                                             terms to 1e-7; a calibration with a diagonal matrix
//                                             gives correct's vectors themselves
//   px4 (gauss), ardupilot (milligauss) mag   a tumbling magnetometer's log in uT: the same moduli,
//                                             converted, to 1e-7, vectors within the reported rotation
//   c (a header for firmware)                 compiled by the system's C compiler (-std=c99 -Werror),
//                                             its scalcal_bench_apply in float on every row: correct's
//                                             vectors to 1e-6 relative (float's 24 bits); its
//                                             OFFSET and MATRIX the file's own to 1e-15
#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "tests/common/export_text.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

struct Data {
  std::string log, calibration;
  std::vector<V3> raw, corrected;  // the log's rows and correct's
  M3 C;
  V3 o;
};

std::vector<std::vector<double>> csv_numbers(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) continue;
    std::vector<double> v;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) v.push_back(std::stod(f));
    rows.push_back(v);
  }
  return rows;
}

// A rehearsal log with visible errors (size 0.01), its calibration, and correct's output.
const Data& data() {
  static const Data d = [] {
    Data d;
    d.log = (scratch_dir() / "export_log.csv").string();
    d.calibration = (scratch_dir() / "export_cal.json").string();
    const CliResult s = run_cli("simulate --program classic18 --noise 1e-4 --log " + d.log +
                                " --still 3 --dwell 3 --rate 50 --size 0.01 --magnitude 9.80665 --seed 4");
    EXPECT_EQ(s.status, 0) << s.err;
    const CliResult c = run_cli("calibrate --measurements " + d.log + " --magnitude 9.80665 --out " + d.calibration +
                                " --suggest 0 --json");
    EXPECT_EQ(c.status, 0) << c.err;
    const CliResult k = run_cli("correct --calibration " + d.calibration + " --measurements " + d.log);
    EXPECT_EQ(k.status, 0) << k.err;
    for (const auto& r : csv_numbers(slurp(d.log))) d.raw.push_back(V3(r[1], r[2], r[3]));
    for (const auto& r : csv_numbers(k.out)) d.corrected.push_back(V3(r[1], r[2], r[3]));
    const Json cal = Json::parse(slurp(d.calibration));
    for (int i = 0; i < 3; ++i) {
      d.o(i) = cal["offset"][i];
      for (int j = 0; j < 3; ++j) d.C(i, j) = cal["matrix"][i][j];
    }
    return d;
  }();
  return d;
}

std::string exported(const std::string& args, const std::string& calibration = "") {
  const CliResult r = run_cli("export " + (calibration.empty() ? data().calibration : calibration) + " " + args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.err;
  return r.out;
}

template <class Apply>
void expect_vectors(Apply apply, double tolerance, const std::string& what) {
  const Data& d = data();
  ASSERT_EQ(d.raw.size(), d.corrected.size());
  ASSERT_GT(d.raw.size(), 100u);
  for (std::size_t i = 0; i < d.raw.size(); ++i) {
    const V3 ours = apply(d.raw[i]);
    ASSERT_LT((ours - d.corrected[i]).norm(), tolerance * d.corrected[i].norm()) << what << " row " << i;
  }
}

TEST(ExportCli, ExactFormsGiveCorrectsVectors) {
  const Json j = Json::parse(exported("--format json"));
  M3 C;
  V3 o;
  for (int i = 0; i < 3; ++i) {
    o(i) = j["offset"][i];
    for (int k = 0; k < 3; ++k) C(i, k) = j["matrix"][i][k];
  }
  EXPECT_EQ(j["format_version"], 2);
  expect_vectors(
      [&](const V3& r) {
        V3 v = C * (r - o);
        return v;
      },
      1e-12, "json");
  // magcal: rows, corrected = (d - b) A.
  const std::string m = exported("--format magcal");
  const auto a = numbers_after(m, "A = [", 9), b = numbers_after(m, "b = [", 3);
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> A(a.data());
  const Eigen::RowVector3d brow(b[0], b[1], b[2]);
  expect_vectors(
      [&](const V3& r) {
        V3 v = ((r.transpose() - brow) * A).transpose();
        return v;
      },
      1e-12, "magcal");
  // imu_tk: T (9, row-major), K (9), B (3); X' = T K (X - B).
  std::istringstream t(exported("--format imu_tk"));
  double n[21];
  for (double& x : n) t >> x;
  ASSERT_TRUE(t) << "imu_tk: 21 numbers";
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> T(n), K(n + 9);
  const V3 B(n[18], n[19], n[20]);
  EXPECT_EQ(T(0, 0), 1);
  expect_vectors(
      [&](const V3& r) {
        V3 v = T * K * (r - B);
        return v;
      },
      1e-12, "imu_tk");
}

TEST(ExportCli, KalibrIsCorrectItself) {
  const std::string k = exported("--format kalibr");
  EXPECT_NE(k.find("imu0:"), std::string::npos);
  const auto tv = numbers_after(k, "  Ta:", 9), rv = numbers_after(k, "R_IMUtoACC:", 9),
             mv = numbers_after(k, "accelerometers:\n    M:", 9);
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Ta(tv.data()), R(rv.data()), M(mv.data());
  EXPECT_EQ(Ta(0, 1), 0);
  EXPECT_EQ(Ta(0, 2), 0);
  EXPECT_EQ(Ta(1, 2), 0);    // lower triangular, as OpenVINS's kalibr model keeps it
  EXPECT_EQ(M3(M), M3(Ta));  // Kalibr's accelerometers M is OpenVINS's Ta
  EXPECT_LT((R * R.transpose() - M3::Identity()).norm(), 1e-12);
  EXPECT_NEAR(R.determinant(), 1, 1e-12);
  // OpenVINS: Da = Ta^-1, R_ACCtoIMU = R_IMUtoACC^T, a = R_ACCtoIMU Da (a_m - b_a); the bias is its own
  // online state, here the calibration's offset.
  const Data& d = data();
  for (std::size_t i = 0; i < d.raw.size(); ++i) {
    const V3 a = R.transpose() * M3(Ta).triangularView<Eigen::Lower>().solve(d.raw[i] - d.o);
    ASSERT_LT((a - d.corrected[i]).norm(), 1e-12 * a.norm()) << i;
  }
}

TEST(ExportCli, AccelerometerParametersDropOnlyTheOffDiagonalTerms) {
  const Data& d = data();
  M3 off = d.C;
  off.diagonal().setZero();
  const auto px4 = parameters(exported("--format px4 --force"));
  const V3 off_px4(px4.at("CAL_ACC0_XOFF"), px4.at("CAL_ACC0_YOFF"), px4.at("CAL_ACC0_ZOFF"));
  const V3 scale_px4(px4.at("CAL_ACC0_XSCALE"), px4.at("CAL_ACC0_YSCALE"), px4.at("CAL_ACC0_ZSCALE"));
  const auto ap = parameters(exported("--format ardupilot --instance 1 --force"));
  const V3 off_ap(ap.at("INS_ACC2OFFS_X"), ap.at("INS_ACC2OFFS_Y"), ap.at("INS_ACC2OFFS_Z"));
  const V3 scale_ap(ap.at("INS_ACC2SCAL_X"), ap.at("INS_ACC2SCAL_Y"), ap.at("INS_ACC2SCAL_Z"));
  for (std::size_t i = 0; i < d.raw.size(); ++i) {
    const V3 without = d.corrected[i] - off * (d.raw[i] - d.o);  // correct's vector less the dropped terms
    ASSERT_LT(((d.raw[i] - off_px4).cwiseProduct(scale_px4) - without).norm(), 1e-7 * without.norm()) << i;
    ASSERT_LT(((d.raw[i] - off_ap).cwiseProduct(scale_ap) - without).norm(), 1e-7 * without.norm()) << i;
  }
  // The dropped share is reported: beyond 1 % refused without --force, and warned about with it.
  const CliResult w = run_cli("export " + d.calibration + " --format px4 --force --json");
  const double dropped = Json::parse(w.out)["dropped_relative"].get<double>();
  EXPECT_GT(dropped, 1e-4);
  EXPECT_NE(w.err.find("cannot carry an accelerometer's non-orthogonality"), std::string::npos) << w.err;
  const CliResult refused = run_cli("export " + d.calibration + " --format px4");
  EXPECT_EQ(refused.status, dropped > 0.01 ? 2 : 0) << refused.err;
  // With a diagonal matrix nothing is dropped: the parameters give correct's vectors themselves.
  const std::string diagonal = write_file("diagonal_cal.json", R"({"converged": true, "offset": [0.01, -0.02, 0.03],
      "units": {"raw": "m/s^2", "physical": "m/s^2"},
      "matrix": [[1.001, 0, 0], [0, 0.998, 0], [0, 0, 1.0004]]})");
  const CliResult k = run_cli("correct --calibration " + diagonal + " --measurements " + d.log);
  const auto rows = csv_numbers(k.out);
  const auto p = parameters(exported("--format px4", diagonal));
  for (std::size_t i = 0; i < d.raw.size(); ++i) {
    const V3 want(rows[i][1], rows[i][2], rows[i][3]);
    const V3 got = (d.raw[i] - V3(p.at("CAL_ACC0_XOFF"), p.at("CAL_ACC0_YOFF"), p.at("CAL_ACC0_ZOFF")))
                       .cwiseProduct(V3(p.at("CAL_ACC0_XSCALE"), p.at("CAL_ACC0_YSCALE"), p.at("CAL_ACC0_ZSCALE")));
    ASSERT_LT((got - want).norm(), 1e-7 * want.norm()) << i;
  }
}

// A magnetometer turned continuously, its log in uT, calibrated with the Earth's field of 50 uT: PX4
// works in gauss, ArduPilot in milligauss, so the driver's output is 0.01 or 10 times the log's.
TEST(ExportCli, MagnetometerParametersKeepTheModuliInTheirUnitsAndTurnByTheReportedRotation) {
  const std::string log = (scratch_dir() / "export_mag.csv").string(),
                    cal = (scratch_dir() / "export_mag.json").string();
  ASSERT_EQ(
      run_cli("simulate --tumble 60 --rate 50 --noise 2e-3 --magnitude 50 --size 0.05 --seed 5 --log " + log).status,
      0);
  const CliResult c = run_cli("calibrate --measurements " + log + " --magnitude 50 --suggest 0 --out " + cal);
  ASSERT_EQ(c.status, 0) << c.err;
  const Json file = Json::parse(slurp(cal));
  EXPECT_EQ(file["instrument"], "mag");
  EXPECT_EQ(file["units"]["physical"], "uT");
  EXPECT_EQ(file["units"]["raw"], "uT");
  const CliResult k = run_cli("correct --calibration " + cal + " --measurements " + log);
  std::vector<V3> raw, corrected;
  for (const auto& r : csv_numbers(slurp(log))) raw.push_back(V3(r[1], r[2], r[3]));
  for (const auto& r : csv_numbers(k.out)) corrected.push_back(V3(r[1], r[2], r[3]));
  ASSERT_EQ(raw.size(), corrected.size());
  const auto px4 = parameters(exported("--format px4 --instance 2", cal));
  M3 S;
  S << px4.at("CAL_MAG2_XSCALE"), px4.at("CAL_MAG2_XODIAG"), px4.at("CAL_MAG2_YODIAG"), px4.at("CAL_MAG2_XODIAG"),
      px4.at("CAL_MAG2_YSCALE"), px4.at("CAL_MAG2_ZODIAG"), px4.at("CAL_MAG2_YODIAG"), px4.at("CAL_MAG2_ZODIAG"),
      px4.at("CAL_MAG2_ZSCALE");
  const V3 off(px4.at("CAL_MAG2_XOFF"), px4.at("CAL_MAG2_YOFF"), px4.at("CAL_MAG2_ZOFF"));
  const auto ap = parameters(exported("--format ardupilot", cal));
  M3 A;
  A << ap.at("COMPASS_DIA_X"), ap.at("COMPASS_ODI_X"), ap.at("COMPASS_ODI_Y"), ap.at("COMPASS_ODI_X"),
      ap.at("COMPASS_DIA_Y"), ap.at("COMPASS_ODI_Z"), ap.at("COMPASS_ODI_Y"), ap.at("COMPASS_ODI_Z"),
      ap.at("COMPASS_DIA_Z");
  const V3 ofs(ap.at("COMPASS_OFS_X"), ap.at("COMPASS_OFS_Y"), ap.at("COMPASS_OFS_Z"));
  const double turn =
      Json::parse(run_cli("export " + cal + " --format px4 --instrument mag --json").out)["rotation_rad"];
  EXPECT_GT(turn, 0);
  EXPECT_LT(turn, 1e-2);  // of order gamma^2
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const V3 gauss = S * (0.01 * raw[i] - off), milligauss = A * (10 * raw[i] + ofs);
    for (const auto& [theirs, per_uT] : {std::pair{gauss, 0.01}, std::pair{milligauss, 10.0}}) {
      const V3 ours = per_uT * corrected[i];
      ASSERT_NEAR(theirs.norm(), ours.norm(), 1e-7 * ours.norm()) << i;
      ASSERT_LT(std::atan2(theirs.cross(ours).norm(), theirs.dot(ours)), turn + 1e-7) << i;
    }
  }
  // An accelerometer's form of a magnetometer's calibration is refused: the file says what it is.
  EXPECT_EQ(run_cli("export " + cal + " --format px4 --instrument accel").status, 2);
}

TEST(ExportCli, TheCHeaderCompilesAndCorrectsLikeCorrect) {
  const std::string header = exported("--format c --name bench");
  const Data& d = data();
  const auto offset = numbers_after(header, "#define SCALCAL_BENCH_OFFSET", 3);
  const auto matrix = numbers_after(header, "#define SCALCAL_BENCH_MATRIX", 9);
  ASSERT_EQ(offset.size(), 3u);
  ASSERT_EQ(matrix.size(), 9u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(offset[static_cast<std::size_t>(i)], d.o(i), 1e-15 * std::abs(d.o(i)) + 1e-300);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(matrix[static_cast<std::size_t>(3 * i + j)], d.C(i, j), 1e-15 * std::abs(d.C(i, j)) + 1e-300);
  }
  EXPECT_NE(header.find("#define SCALCAL_BENCH_INSTRUMENT \"accel\""), std::string::npos) << header;
  EXPECT_NE(header.find("#define SCALCAL_BENCH_UNITS_PHYSICAL \"m/s^2\""), std::string::npos) << header;
  const auto dir = scratch_dir() / "c_header";
  std::filesystem::create_directories(dir);
  write_file("c_header/bench.h", header);
  write_file("c_header/apply.c",
             "#include <stdio.h>\n#include \"bench.h\"\n"
             "int main(void) {\n  float raw[3], out[3];\n"
             "  while (scanf(\"%f %f %f\", &raw[0], &raw[1], &raw[2]) == 3) {\n"
             "    scalcal_bench_apply(raw, out);\n    printf(\"%.9g,%.9g,%.9g\\n\", out[0], out[1], out[2]);\n  }\n"
             "  return 0;\n}\n");
  std::string rows;
  for (const V3& r : d.raw)
    rows += std::to_string(r(0)) + " " + std::to_string(r(1)) + " " + std::to_string(r(2)) + "\n";
  write_file("c_header/raw.txt", rows);
  const std::string program = (dir / "apply").string();
  ASSERT_EQ(std::system(("cc -std=c99 -Wall -Wextra -Werror -pedantic -o " + program + " " +
                         (dir / "apply.c").string() + " 2> " + (dir / "cc.err").string())
                            .c_str()),
            0)
      << slurp((dir / "cc.err").string());
  ASSERT_EQ(std::system((program + " < " + (dir / "raw.txt").string() + " > " + (dir / "out.txt").string()).c_str()),
            0);
  std::vector<V3> applied;
  for (const auto& r : csv_numbers(slurp((dir / "out.txt").string()))) applied.push_back(V3(r[0], r[1], r[2]));
  ASSERT_EQ(applied.size(), d.raw.size());
  std::size_t i = 0;
  expect_vectors([&](const V3&) { return applied[i++]; }, 1e-6, "c");
}

TEST(ExportCli, TheCalibrationFileSaysWhatItIs) {
  const Json cal = Json::parse(slurp(data().calibration));
  EXPECT_EQ(cal["format_version"], 2);
  EXPECT_TRUE(std::regex_match(cal["created"].get<std::string>(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_EQ(cal["tool"]["name"], "scalcal");
  EXPECT_EQ(cal["instrument"], "accel");  // --magnitude 9.80665 is gravity in m/s^2
  EXPECT_EQ(cal["units"]["physical"], "m/s^2");
  EXPECT_EQ(cal["units"]["raw"], "m/s^2");  // the log was within 10 % of it: no ellipsoid start
  for (const char* key : {"sensor", "units", "magnitude", "model", "region", "converged", "offset", "matrix"})
    EXPECT_TRUE(cal.contains(key)) << key;
  for (const auto& [args, why] : std::vector<std::pair<std::string, std::string>>{
           {"--format imu_tk --instrument mag", "contradicts the accel calibration"},
           {"--format ardupilot --instance 4 --force", ""},
           {"--format px4 --instance 4", "has 4 accelerometer instances"},
           {"--format PX4", "got 'PX4'"},
           {"--format px4 --raw-scale 0.01uT", "not a unit of acceleration"},
           {"--format px4 --raw-scale furlong", "expected a positive size with its unit"},
           {"--format c --name 9lives", "must be a C identifier"},
           {"--format c --name 'a-b'", "must be a C identifier"}}) {
    const CliResult r = run_cli("export " + data().calibration + " " + args);
    EXPECT_EQ(r.status, why.empty() ? 0 : 2) << args << ": " << r.err;
    if (!why.empty()) {
      EXPECT_NE(r.err.find(why), std::string::npos) << args << ": " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
  }
}

}  // namespace
}  // namespace scalcal::testing
