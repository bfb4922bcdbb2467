// Thermal exports (issue 53): a thermal calibration written for PX4 (TC_A0_X0..X3 about TC_A0_TREF, then
// CAL_ACC0_*) and ArduPilot (INS_TCAL1_ACC1..3 in 1e-6 units about 35 degC, zero at INS_ACC1_CALTEMP, then
// INS_ACCOFFS/INS_ACCSCAL), applied here the firmware's way as their sources write it
// (docs/thermal_export_sources.md), against `scalcal correct` at each row's temperature, and the offset
// polynomial against the calibration file's own per-degC coefficients re-evaluated by hand.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "numeric/program/catalogue.hpp"
#include "tests/common/export_text.hpp"
#include "tests/common/run_cli.hpp"
#include "tests/thermal/thermal_programs.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

constexpr double kStandardGravity = 9.80665;  // m/s^2 per g (CGPM 1901)

std::string scratch(const std::string& name) { return (testing::scratch_dir() / ("thermal_export_" + name)).string(); }

std::string write_program(const std::vector<double>& setpoints, const std::string& name) {
  return testing::write_thermal_program(setpoints, scratch(name));
}

// A rehearsal of `model` over the set-points, calibrated in g; returns the calibration file.
std::string calibration(const std::string& model, const std::vector<double>& setpoints, const std::string& range,
                        const std::string& name) {
  const std::string program = write_program(setpoints, name + "_program.csv"), log = scratch(name + "_log.csv"),
                    cal = scratch(name + "_cal.json");
  const CliResult s = run_cli({"simulate", "--program", program, "--model", model, "--temperature", range, "--log", log,
                               "--noise", "1e-3", "--size", "3e-3", "--seed", "5", "--rate", "50", "--dwell", "4"});
  EXPECT_EQ(s.status, 0) << s.err;
  const CliResult c = run_cli({"calibrate", "--measurements", log, "--model", model, "--magnitude", "1", "--instrument",
                               "accel", "--temperature", range, "--out", cal});
  EXPECT_EQ(c.status, 0) << c.err;
  return cal;
}

struct Row {
  double celsius;
  double raw[3];
};

// Raw rows (g) near the unit sphere at temperatures across and beyond the range (the firmware clamps).
std::vector<Row> rows(double low, double high) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n;
  std::vector<Row> out;
  for (int i = 0; i <= 40; ++i) {
    Row r{low - 10 + (high - low + 20) * i / 40, {n(rng), n(rng), n(rng)}};
    const double norm = std::sqrt(r.raw[0] * r.raw[0] + r.raw[1] * r.raw[1] + r.raw[2] * r.raw[2]);
    for (double& v : r.raw) v /= norm;
    out.push_back(r);
  }
  return out;
}

// `scalcal correct` on the rows: corrected vectors in g, and its warnings.
std::vector<std::vector<double>> corrected(const std::string& cal, const std::vector<Row>& data, std::string& err) {
  const std::string file = scratch("rows.csv");
  {
    std::ofstream out(file);
    out.precision(17);
    out << "ix,iy,iz,temp\n";
    for (const auto& r : data) out << r.raw[0] << "," << r.raw[1] << "," << r.raw[2] << "," << r.celsius << "\n";
  }
  const CliResult c = run_cli({"correct", "--calibration", cal, "--measurements", file});
  EXPECT_EQ(c.status, 0) << c.err;
  err = c.err;
  std::vector<std::vector<double>> out;
  std::istringstream in(c.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t_c,x,y,z,modulus");
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) v.push_back(std::stod(f));
    out.push_back({v[1], v[2], v[3]});
  }
  return out;
}

// The calibration file's offset at T (g): |I| (b0 + sum_j value_per_degc_j (T - reference)^j), T clamped.
double file_offset(const nlohmann::json& cal, int axis, double celsius) {
  const char* names[3] = {"bias_x", "bias_y", "bias_z"};
  const auto& p = cal["parameters"];
  const double low = cal["reference_c"].get<double>() - cal["half_range_c"].get<double>();
  const double high = cal["reference_c"].get<double>() + cal["half_range_c"].get<double>();
  const double x = std::clamp(celsius, low, high) - cal["reference_c"].get<double>();
  double o = p[names[axis]]["value"].get<double>();
  for (int j = 1; p.contains(std::string(names[axis]) + "_T" + std::to_string(j)); ++j)
    o += p[std::string(names[axis]) + "_T" + std::to_string(j)]["value_per_degc"].get<double>() * std::pow(x, j);
  return cal["magnitude"].get<double>() * o;
}

struct Export {
  std::map<std::string, double> p;
  double dropped = 0;
};

Export export_of(const std::string& cal, const std::string& format) {
  const CliResult e = run_cli({"export", cal, "--format", format, "--json"});
  EXPECT_EQ(e.status, 0) << e.err;
  const auto j = nlohmann::json::parse(e.out);
  return {testing::parameters(j["text"].get<std::string>()), j["dropped_relative"].get<double>()};
}

const char* const kAxis[3] = {"X", "Y", "Z"};

// PX4: (v - P(clamp(T) - TREF) - CAL_ACC0_?OFF) .* CAL_ACC0_?SCALE (TemperatureCompensation.cpp, Accelerometer.hpp).
double px4_offset(const std::map<std::string, double>& p, int k, double celsius) {
  const double dt = std::clamp(celsius, p.at("TC_A0_TMIN"), p.at("TC_A0_TMAX")) - p.at("TC_A0_TREF");
  const std::string a = "_" + std::to_string(k);
  return p.at("TC_A0_X0" + a) + p.at("TC_A0_X1" + a) * dt + p.at("TC_A0_X2" + a) * dt * dt +
         p.at("TC_A0_X3" + a) * dt * dt * dt + p.at(std::string("CAL_ACC0_") + kAxis[k] + "OFF");
}
double px4_scale(const std::map<std::string, double>& p, int k) {
  return p.at(std::string("CAL_ACC0_") + kAxis[k] + "SCALE");
}

// ArduPilot: v - P(T' - 35) + P(Tc' - 35) - INS_ACCOFFS, then .* INS_ACCSCAL (AP_InertialSensor_tempcal.cpp).
double ardupilot_offset(const std::map<std::string, double>& p, int k, double celsius) {
  const auto poly = [&](double x) {
    const std::string a = std::string("_") + kAxis[k];
    return 1e-6 * (p.at("INS_TCAL1_ACC1" + a) * x + p.at("INS_TCAL1_ACC2" + a) * x * x +
                   p.at("INS_TCAL1_ACC3" + a) * x * x * x);
  };
  const double lo = p.at("INS_TCAL1_TMIN"), hi = p.at("INS_TCAL1_TMAX");
  return poly(std::clamp(celsius, lo, hi) - 35) - poly(std::clamp(p.at("INS_ACC1_CALTEMP"), lo, hi) - 35) +
         p.at(std::string("INS_ACCOFFS_") + kAxis[k]);
}
double ardupilot_scale(const std::map<std::string, double>& p, int k) {
  return p.at(std::string("INS_ACCSCAL_") + kAxis[k]);
}

// Both firmware forms equal the calibration's offset polynomial (to float32) and `correct` (to what they drop).
void check_firmware_forms(const std::string& cal_path, double low, double high) {
  std::ifstream in(cal_path);
  const auto cal = nlohmann::json::parse(in);
  const std::vector<Row> data = rows(low, high);
  std::string err;
  const auto want = corrected(cal_path, data, err);
  EXPECT_NE(err.find("row(s) outside the calibration's"), std::string::npos) << err;
  ASSERT_EQ(want.size(), data.size());
  for (const std::string format : {"px4", "ardupilot"}) {
    const Export e = export_of(cal_path, format);
    const bool px4 = format == "px4";
    EXPECT_LT(e.dropped, 0.01);
    double worst_offset = 0, worst_vector = 0;
    for (std::size_t i = 0; i < data.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const double v = kStandardGravity * data[i].raw[k];
        const double offset = px4 ? px4_offset(e.p, k, data[i].celsius) : ardupilot_offset(e.p, k, data[i].celsius);
        const double scale = px4 ? px4_scale(e.p, k) : ardupilot_scale(e.p, k);
        worst_offset =
            std::max(worst_offset, std::abs(offset - kStandardGravity * file_offset(cal, k, data[i].celsius)));
        worst_vector = std::max(worst_vector, std::abs((v - offset) * scale - kStandardGravity * want[i][k]));
      }
    // float32 parameters: 9 significant digits of offsets near 0.05 m/s^2 and coefficients up to 1e-3 x 40^j.
    EXPECT_LT(worst_offset, 1e-7 * kStandardGravity) << format;
    EXPECT_LT(worst_vector, (e.dropped + 1e-6) * 1.1 * kStandardGravity) << format;
    EXPECT_GT(worst_vector, 0.0) << format;
  }
}

TEST(ThermalExport, FirmwareFormsEqualCorrectAtEveryTemperature) {
  check_firmware_forms(calibration("paper9+bias:T3", {-20, 0, 35, 60}, "-20..60", "bias3"), -20, 60);
}

TEST(ThermalExport, ArduPilotCalTempHeldInsideARangeBelow35) {
  const std::string cal = calibration("paper9+bias:T2", {-20, 0, 25}, "-20..25", "cold");
  EXPECT_EQ(export_of(cal, "ardupilot").p.at("INS_ACC1_CALTEMP"), 25);
  check_firmware_forms(cal, -20, 25);
}

TEST(ThermalExport, WhatTheTargetsCannotCarryIsRefused) {
  const std::string cal = calibration("paper9+T4", {-20, -5, 10, 25, 40}, "-20..40", "t4");
  for (const char* format : {"px4", "ardupilot"}) {
    const CliResult e = run_cli({"export", cal, "--format", format});
    EXPECT_EQ(e.status, 2);
    EXPECT_NE(e.err.find("degree 3 at most"), std::string::npos) << e.err;
  }
  const std::string t3 = calibration("paper9+T3", {-20, 0, 20, 40}, "-20..40", "t3");
  for (const char* format : {"json", "c", "kalibr", "imu_tk", "magcal"}) {
    const CliResult e = run_cli({"export", t3, "--format", format});
    EXPECT_EQ(e.status, 2) << format;
    EXPECT_NE(e.err.find("carries no temperature drift"), std::string::npos) << e.err;
  }
  // The scales' drift is what PX4 drops: over 1 % of a vector here (drift 3e-3 per tau^j at tau = +-1),
  // refused with its size, written with --force and a warning.
  const CliResult px4 = run_cli({"export", t3, "--format", "px4"});
  EXPECT_EQ(px4.status, 2);
  EXPECT_NE(px4.err.find("temperature drift"), std::string::npos) << px4.err;
  const CliResult forced = run_cli({"export", t3, "--format", "px4", "--force"});
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_NE(forced.err.find("warning: the px4 export cannot carry"), std::string::npos) << forced.err;
  const CliResult mag = run_cli({"export", t3, "--format", "px4", "--instrument", "mag"});
  EXPECT_EQ(mag.status, 2);
  // Without the temperature, correct cannot apply a thermal calibration.
  const std::string untimed = scratch("untimed.csv");
  std::ofstream(untimed) << "ix,iy,iz\n0,0,1\n";
  const CliResult plain = run_cli({"correct", "--calibration", t3, "--measurements", untimed});
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(plain.err.find("need their temperature"), std::string::npos) << plain.err;
}

}  // namespace
}  // namespace scalcal
