// `scalcal calibrate` on raw logs and `scalcal correct` as a user runs them (issue 12): the real
// Xsens log end to end, a simulated counts log, the JSON keys the issue fixes, and the refusals.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/calibration/raw_log_simulator.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;
using namespace calibration_test;

const std::string kXsens = std::string(SCALCAL_SOURCE_DIR) + "/data/xsens_acc.txt";

TEST(RawCalibrateCli, XsensEndToEnd) {
  const std::string cal = (scratch_dir() / "xsens_cal.json").string();
  const auto r = run_cli("calibrate --measurements " + kXsens + " --magnitude 9.81744 --json --out " + cal);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  // --out holds the same object after the calibration file's header (issue 32).
  Json file = Json::parse(slurp(cal));
  for (const char* key : {"format_version", "created", "tool", "sensor", "units", "units_reason", "region"}) {
    EXPECT_TRUE(file.contains(key)) << key;
    if (!j.contains(key)) file.erase(key);
  }
  EXPECT_EQ(file, j);
  for (const char* key : {"bias", "scale_deviation", "nonorthogonality", "bias_std", "offset", "matrix", "intervals",
                          "program", "outliers", "suggested", "predicted_std", "achieved_std"})
    EXPECT_TRUE(j.contains(key)) << key;
  ASSERT_GE(j["intervals"].size(), 30u);
  for (const auto& iv : j["intervals"]) {
    EXPECT_LE(iv["start"].get<double>(), iv["end"].get<double>());
    EXPECT_GE(iv["samples"].get<int>(), 30);  // 0.3 s poses at 100 Hz at the shortest (adaptive_detection.hpp)
  }
  EXPECT_EQ(j["matrix"].size(), 3u);
  EXPECT_EQ(j["program"]["positions"].get<int>(), static_cast<int>(j["intervals"].size()));
  EXPECT_EQ(j["suggested"].size(), 3u);
  // Each suggestion improves D (the program grows by one position each time).
  double d = j["program"]["D"];
  for (const auto& s : j["suggested"]) {
    EXPECT_LT(s["D"].get<double>(), d);
    d = s["D"];
  }
  // Applying it: every static sample's modulus is g to the sensor's noise (about 1e-3 of g).
  const auto c = run_cli("correct --calibration " + cal + " --measurements " + kXsens);
  ASSERT_EQ(c.status, 0) << c.err;
  std::istringstream rows(c.out);
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "t,x,y,z,modulus");
  double ss = 0;
  int count = 0;
  const auto& first = j["intervals"][0];
  while (std::getline(rows, line)) {
    double t, x, y, z, m;
    char comma;
    std::istringstream f(line);
    f >> t >> comma >> x >> comma >> y >> comma >> z >> comma >> m;
    if (t < first["start"].get<double>() || t > first["end"].get<double>()) continue;
    ss += (m / 9.81744 - 1) * (m / 9.81744 - 1);
    ++count;
  }
  ASSERT_GT(count, 5000);
  EXPECT_LT(std::sqrt(ss / count), 2e-3);
}

TEST(RawCalibrateCli, CsvLogWithDropoutsCountsThem) {
  LogSpec spec;
  spec.meter = example_meter(0.01, spec.magnitude);
  const SimulatedLog s = simulate_log(spec, fourteen_directions());
  std::istringstream in(s.text);
  std::string csv = "t,ix,iy,iz\n", line;
  for (int k = 0; std::getline(in, line); ++k) {
    std::istringstream f(line);
    double t, x, y, z;
    f >> t >> x >> y >> z;
    csv += std::to_string(t) + "," + (k == 4321 ? std::string("nan") : std::to_string(x)) + "," + std::to_string(y) +
           "," + std::to_string(z) + "\n";
  }
  const auto path = write_file("dropout_log.csv", csv);
  const auto r = run_cli("calibrate --measurements " + path + " --magnitude 9.81 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["nonfinite_rows"].get<int>(), 1);
  EXPECT_EQ(j["intervals"].size(), 14u);
  EXPECT_NE(r.err.find("1 rows with a NaN or infinite value are not used (lines 4323)"), std::string::npos) << r.err;
}

TEST(RawCalibrateCli, TooFewIntervalsSaysWhy) {
  const auto r = run_cli("calibrate --measurements " + kXsens + " --magnitude 9.81744 --min-interval 60");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("found 0 static intervals"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--threshold-factor"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(RawCalibrateCli, MagnitudeAutoNamesWhatIsNotIdentifiable) {
  const auto r = run_cli("calibrate --measurements " + kXsens + " --magnitude auto --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["magnitude"], "auto");
  bool named = false;
  for (const auto& what : j["not_identifiable"])
    named = named || what.get<std::string>().find("field's strength") != std::string::npos;
  EXPECT_TRUE(named) << j["not_identifiable"];
  double logsum = 0;
  for (const auto& v : j["scale_deviation"]) logsum += std::log1p(v.get<double>());
  EXPECT_NEAR(logsum, 0.0, 1e-12);  // relative to their geometric mean
}

TEST(CorrectCli, RefusesABadCalibrationFile) {
  for (const auto& [name, text, words] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"notjson.json", "offset: 1", "not a JSON object"},
           {"nokeys.json", "{\"bias\": [0, 0, 0]}", "needs the keys 'offset' and 'matrix'"},
           {"short.json", "{\"offset\": [0, 0], \"matrix\": [[1,0,0],[0,1,0],[0,0,1]]}",
            "'offset' must be three numbers"},
           {"singular.json", "{\"offset\": [0, 0, 0], \"matrix\": [[1,0,0],[1,0,0],[0,0,1]]}", "singular"}}) {
    const auto r = run_cli("correct --calibration " + write_file(name, text) + " --measurements " + kXsens);
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find(words), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace scalcal::testing
