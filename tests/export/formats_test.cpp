// The export formats (numeric/export): each target's numbers against values derived by hand from a
// calibration chosen so that they are simple, each refusal with its reason. How a firmware applies
// them (offsets first, then scales; ArduPilot's compass adds its offsets) is written out in each
// test from the firmware's source, as the comments of numeric/export/*_format.cpp cite it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/export/export_format.hpp"
#include "numeric/export/matrix_forms.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

double parameter(const ExportOutput& out, const std::string& name) {
  for (const auto& p : out.parameters)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no parameter " << name << " in\n" << out.text;
  return NAN;
}

// A log in counts of 0.01 m/s^2 each: C maps counts to m/s^2.
ExportInput counts_accelerometer() {
  ExportInput in;
  in.file = "cal.json";
  in.instrument = Instrument::accel;
  in.correction.offset = Vec3(10, -20, 5);
  in.correction.matrix = Vec3(0.0101, 0.0099, 0.01).asDiagonal();
  in.units.physical = parse_unit("m/s^2");
  in.raw_scale = parse_amount("0.01m/s^2");
  return in;
}

ExportOutput run(const char* format, const ExportInput& in) { return export_with(*find_export_format(format), in); }

TEST(ExportFormats, FirmwareParametersAreInTheFirmwaresUnits) {
  ExportInput in = counts_accelerometer();
  // PX4: corrected = (v - OFF) .* SCALE with v = 0.01 raw m/s^2: OFF = 0.01 o, SCALE = C_ii / 0.01.
  const ExportOutput px4 = run("px4", in);
  EXPECT_NEAR(parameter(px4, "CAL_ACC0_XOFF"), 0.1, 1e-15);
  EXPECT_NEAR(parameter(px4, "CAL_ACC0_YOFF"), -0.2, 1e-15);
  EXPECT_NEAR(parameter(px4, "CAL_ACC0_XSCALE"), 1.01, 1e-14);
  EXPECT_NEAR(parameter(px4, "CAL_ACC0_YSCALE"), 0.99, 1e-14);
  // ArduPilot's fourth IMU is the group INS4_.
  in.instance = 3;
  const ExportOutput ap = run("ardupilot", in);
  EXPECT_NEAR(parameter(ap, "INS4_ACCOFFS_Z"), 0.05, 1e-15);
  EXPECT_NEAR(parameter(ap, "INS4_ACCSCAL_Z"), 1.0, 1e-14);
  // A log in mg calibrated to g: the driver's m/s^2 in and out, so the scale is 1.
  ExportInput g = counts_accelerometer();
  g.raw_scale.reset();
  g.units.raw = parse_unit("mg");
  g.units.physical = parse_unit("g");
  g.correction.matrix = Mat3::Identity() * 1e-3;
  EXPECT_NEAR(parameter(run("px4", g), "CAL_ACC0_XSCALE"), 1, 1e-15);
  EXPECT_NEAR(parameter(run("px4", g), "CAL_ACC0_XOFF"), 10 * 9.80665e-3, 1e-15);
}

TEST(ExportFormats, AMagnetometerOfUnknownFieldKeepsTheDriversScale) {
  // |C (raw - o)| = 1 on the field, which is 500 counts of 1/12 mG: ArduPilot's M = F C = I here,
  // COMPASS_OFS = -o in mG; PX4 takes gauss.
  ExportInput in;
  in.file = "mag.json";
  in.instrument = Instrument::mag;
  in.correction.offset = Vec3(120, -60, 30);
  in.correction.matrix = Mat3::Identity() / 500;
  in.units.unit_modulus = true;
  in.units.field_strength = 500;
  in.raw_scale = parse_amount("1/12 mG");
  const ExportOutput ap = run("ardupilot", in);
  EXPECT_NEAR(parameter(ap, "COMPASS_OFS_X"), -10, 1e-13);
  EXPECT_NEAR(parameter(ap, "COMPASS_OFS_Y"), 5, 1e-13);
  EXPECT_NEAR(parameter(ap, "COMPASS_DIA_X"), 1, 1e-14);
  EXPECT_NEAR(parameter(ap, "COMPASS_ODI_X"), 0, 1e-14);
  const ExportOutput px4 = run("px4", in);
  EXPECT_NEAR(parameter(px4, "CAL_MAG0_XOFF"), 0.01, 1e-15);
  // Without the raw scale the offsets' units are unknown: refused, saying what is missing.
  in.raw_scale.reset();
  try {
    run("ardupilot", in);
    ADD_FAILURE() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("what one raw unit"), std::string::npos) << e.what();
  }
  // An accelerometer calibrated with its magnitude unknown has no gain for a firmware.
  in.raw_scale = parse_amount("0.01m/s^2");
  in.instrument = Instrument::accel;
  EXPECT_THROW(run("px4", in), InputError);
}

TEST(ExportFormats, WhatATargetCannotHoldIsRefused) {
  ExportInput in = counts_accelerometer();
  // ArduPilot documents INS_ACCOFFS in -3.5 .. 3.5 m/s^2: 500 counts are 5 m/s^2.
  in.correction.offset = Vec3(500, 0, 0);
  EXPECT_THROW(run("ardupilot", in), InputError);
  in.force = true;
  const ExportOutput forced = run("ardupilot", in);
  EXPECT_NEAR(parameter(forced, "INS_ACCOFFS_X"), 5, 1e-13);
  ASSERT_FALSE(forced.warnings.empty());
  // Beyond float32 nothing is written, forced or not.
  in.correction.offset = Vec3(1e41, 0, 0);
  EXPECT_THROW(run("px4", in), InputError);
  in.correction.offset = Vec3(1e-320, 0, 0);
  EXPECT_THROW(run("px4", in), InputError);
  // A permuted matrix: px4's diagonal keeps nothing of it (100 % dropped).
  in = counts_accelerometer();
  Mat3 P = Mat3::Zero();
  P(0, 1) = P(1, 2) = P(2, 0) = 0.01;
  in.correction.matrix = P;
  EXPECT_THROW(run("px4", in), InputError);
  EXPECT_THROW(run("imu_tk", in), InputError);  // T K with K = diag(C) = 0
  // Instances a firmware does not have.
  in = counts_accelerometer();
  in.instance = 5;
  EXPECT_THROW(run("ardupilot", in), RequestError);
  in.instance = 4;
  EXPECT_THROW(run("px4", in), RequestError);
  in.instance = 3;
  in.instrument = Instrument::mag;
  in.units.physical = parse_unit("uT");
  in.raw_scale = parse_amount("0.1uT");
  EXPECT_THROW(run("ardupilot", in), RequestError);  // COMPASS_OFS, OFS2, OFS3 only
  // Kalibr's rotation cannot be a reflection.
  in = counts_accelerometer();
  in.correction.matrix(2, 2) = -0.01;
  EXPECT_THROW(run("kalibr", in), InputError);
  // A magnetometer has no Kalibr form.
  in = counts_accelerometer();
  in.instrument = Instrument::mag;
  in.units.physical = parse_unit("uT");
  in.raw_scale = parse_amount("0.1uT");
  EXPECT_THROW(run("kalibr", in), RequestError);
}

TEST(ExportFormats, AMagnetometersSymmetricFormTurnsOnlyWhatScalarCalibrationLeavesOpen) {
  // A matrix in scalcal's convention (full_correction.hpp) holds no rotation beyond it; the same with a
  // 30-degree mounting rotation composed in holds 30 degrees, which PX4's symmetric S would lose.
  Mat3 C;
  C << 1.05, 0.02, -0.01, 0.02, 0.93, 0.03, -0.01, 0.03, 1.1;
  const auto canonical = canonical_correction(C, Vec3::Zero());
  ASSERT_TRUE(canonical);
  EXPECT_LT(rotation_beyond_convention(canonical->matrix), 1e-12);
  const Mat3 R = Eigen::AngleAxisd(M_PI / 6, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_NEAR(rotation_beyond_convention(R * canonical->matrix), M_PI / 6, 1e-12);
  ExportInput in;
  in.file = "mag.json";
  in.instrument = Instrument::mag;
  in.units.raw = in.units.physical = parse_unit("uT");
  in.correction.matrix = canonical->matrix;
  const ExportOutput fine = run("px4", in);
  EXPECT_GT(fine.rotation_rad, 0);  // S and scalcal's matrix differ by a turn neither determines
  in.correction.matrix = R * canonical->matrix;
  EXPECT_THROW(run("px4", in), InputError);
  in.force = true;
  EXPECT_NO_THROW(run("ardupilot", in));
}

TEST(ExportFormats, RotationTimesLowerTriangleRebuildsTheMatrix) {
  Mat3 C;
  C << 1.01, 0.02, -0.01, 0.015, 0.99, 0.03, -0.02, 0.01, 1.003;
  const auto f = rotation_times_lower(C);
  ASSERT_TRUE(f);
  EXPECT_LT((f->rotation * f->lower - C).norm(), 1e-15);
  EXPECT_LT((f->rotation * f->rotation.transpose() - Mat3::Identity()).norm(), 1e-15);
  EXPECT_NEAR(f->rotation.determinant(), 1, 1e-15);
  EXPECT_EQ(f->lower(0, 1), 0);
  EXPECT_EQ(f->lower(0, 2), 0);
  EXPECT_EQ(f->lower(1, 2), 0);
  EXPECT_GT(f->lower.diagonal().minCoeff(), 0);
  EXPECT_FALSE(rotation_times_lower(Mat3(Vec3(1, 1, -1).asDiagonal())));
}

TEST(ExportFormats, EveryRegisteredFormatIsFoundByItsName) {
  for (const auto& f : export_formats()) EXPECT_EQ(find_export_format(f.name), &f);
  EXPECT_EQ(find_export_format("PX4"), nullptr);  // names are exact: no writer by default
  EXPECT_EQ(export_format_names(), "json, magcal, imu_tk, kalibr, px4, ardupilot, c");
}

}  // namespace
}  // namespace scalcal
