// Every real log of data/ (issue 31's "Done when"): `calibrate` with no option but --magnitude
// (and --rate where the file has no time) picks the model expected for the layout, converges, and
// reaches an RMS of |corrected mean| - |I| within 1.05 times the independent SciPy fit's
// (experiments/docs/real_data_fit.py, its output real_data_fit.json). An accelerometer's log with the
// default detection (1 s window, factor 6, 1 s poses: the script's) finds the intervals the script
// finds; the magnetometer's tumbling log is fitted sample by sample by both (issue 49), with the same
// samples left out. A log that is neither in
// data/ nor in ../shared/data (logs whose licence lets the project's shared data hold them, see
// data/README.md) or SCALCAL_REAL_DATA is skipped with its name.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "commands/calibration/calibrate.hpp"

namespace scalcal {
namespace {

nlohmann::json independent_fits() {
  std::ifstream in(std::string(SCALCAL_SOURCE_DIR) + "/experiments/docs/real_data_fit.json");
  return nlohmann::json::parse(in);
}

// data/, the shared data beside the repository, or SCALCAL_REAL_DATA (a folder holding the logs).
std::string find_log(const std::string& file) {
  const std::filesystem::path root(SCALCAL_SOURCE_DIR);
  std::vector<std::filesystem::path> dirs = {root / "data", root.parent_path() / "shared" / "data"};
  if (const char* extra = std::getenv("SCALCAL_REAL_DATA")) dirs.emplace_back(extra);
  for (const auto& dir : dirs)
    if (std::filesystem::exists(dir / file)) return (dir / file).string();
  return "";
}

class RealLog : public testing::TestWithParam<std::string> {};

TEST_P(RealLog, AsGoodAsTheIndependentFit) {
  const nlohmann::json fit = independent_fits()["logs"][GetParam()];
  ASSERT_TRUE(fit.is_object()) << GetParam() << " is not in real_data_fit.json";
  const std::string path = find_log(fit["file"].get<std::string>());
  if (path.empty()) GTEST_SKIP() << fit["file"] << " is in neither data/ nor ../shared/data";
  commands::CalibrateRequest q;
  q.file = path;
  if (!fit["magnitude"].is_null()) q.magnitude = fit["magnitude"].get<double>();
  q.rate = fit["rate"].is_null() ? 0.0 : fit["rate"].get<double>();
  q.suggest = 0;
  q.intervals_given = true;  // the default detection, as the script's
  const commands::CalibrateResult r = commands::calibrate(q);
  EXPECT_EQ(static_cast<int>(r.positions.size()), fit["intervals"].get<int>());
  EXPECT_EQ(r.tumbling.has_value(), fit.contains("every")) << GetParam();
  EXPECT_EQ(model_name(r.model), fit["model"].get<std::string>()) << r.model_reason;
  EXPECT_TRUE(r.converged()) << r.fit.estimate.summary.message;
  double ss = 0;
  for (const auto& p : r.positions) ss += p.residual * p.residual;
  const double rms = std::sqrt(ss / static_cast<double>(r.positions.size())) / r.fit.magnitude;
  const double independent = fit["rms_means_relative"].get<double>();
  EXPECT_LT(rms, 1.05 * independent) << GetParam() << ": scalcal " << rms << ", independent " << independent;
  RecordProperty("rms_ratio", std::to_string(rms / independent));
}

INSTANTIATE_TEST_SUITE_P(Logs, RealLog, testing::Values("xsens", "mpu6050", "nilspod_ferraris", "qmc5883l"));

// Taken as a stream (--chunk: 7 rows, 100 rows at a time), each sample judged once from the rows
// before it: the same number of poses as the independent script's batch detection finds, the same
// model, and the RMS within the same 1.05 of its fit's.
class StreamedRealLog : public testing::TestWithParam<std::string> {};

TEST_P(StreamedRealLog, AsGoodAsTheIndependentFit) {
  const nlohmann::json fit = independent_fits()["logs"][GetParam()];
  const std::string path = find_log(fit["file"].get<std::string>());
  if (path.empty()) GTEST_SKIP() << fit["file"] << " is in neither data/ nor ../shared/data";
  for (int chunk : {7, 100}) {
    commands::CalibrateRequest q;
    q.file = path;
    if (!fit["magnitude"].is_null()) q.magnitude = fit["magnitude"].get<double>();
    q.rate = fit["rate"].is_null() ? 0.0 : fit["rate"].get<double>();
    q.suggest = 0;
    q.intervals_given = true;
    q.chunk_rows = chunk;
    const commands::CalibrateResult r = commands::calibrate(q);
    EXPECT_EQ(r.chunks, (r.rows + chunk - 1) / chunk);
    EXPECT_EQ(static_cast<int>(r.positions.size()), fit["intervals"].get<int>()) << chunk;
    EXPECT_EQ(model_name(r.model), fit["model"].get<std::string>()) << r.model_reason;
    EXPECT_TRUE(r.converged()) << r.fit.estimate.summary.message;
    double ss = 0;
    for (const auto& p : r.positions) ss += p.residual * p.residual;
    const double rms = std::sqrt(ss / static_cast<double>(r.positions.size())) / r.fit.magnitude;
    EXPECT_LT(rms, 1.05 * fit["rms_means_relative"].get<double>()) << GetParam() << " in chunks of " << chunk;
  }
}

INSTANTIATE_TEST_SUITE_P(Logs, StreamedRealLog, testing::Values("xsens", "mpu6050", "nilspod_ferraris", "qmc5883l"));

}  // namespace
}  // namespace scalcal
