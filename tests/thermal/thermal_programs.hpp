// What the thermal tests share: the dodecahedron's 12 face normals at given set-points as a program file, and a
// rehearsal calibrated under its model with each coefficient's standardised error against the truth.
#pragma once
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "numeric/program/catalogue.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {

// x,y,z,t_c rows: every normal at each set-point, set-points in the given order.
inline std::string write_thermal_program(const std::vector<double>& setpoints, const std::string& path) {
  std::ofstream out(path);
  out << "x,y,z,t_c\n";
  const Program p = *named_program("dodecahedral-12");
  for (double t : setpoints)
    for (const auto& e : p.positions) out << e(0) << "," << e(1) << "," << e(2) << "," << t << "\n";
  return path;
}

// simulate ARGS --log --truth --seed SEED, then calibrate under `model` over `range`: (estimate - truth) / standard
// error of every coefficient appended to z; the number of poses found is returned (0 on a failed command).
inline std::size_t standardised_errors(const std::vector<std::string>& simulate, const std::string& model,
                                       const std::string& range, int seed, const std::string& scratch,
                                       std::vector<double>& z) {
  const std::string log = scratch + "_log.csv", truth = scratch + "_truth.json";
  std::vector<std::string> args = simulate;
  for (const std::string& a :
       {std::string("--log"), log, std::string("--truth"), truth, std::string("--seed"), std::to_string(seed)})
    args.push_back(a);
  const CliResult s = run_cli(args);
  EXPECT_EQ(s.status, 0) << s.err;
  const CliResult c = run_cli(
      {"calibrate", "--measurements", log, "--model", model, "--magnitude", "1", "--temperature", range, "--json"});
  EXPECT_EQ(c.status, 0) << c.err;
  if (s.status != 0 || c.status != 0) return 0;
  const auto fit = nlohmann::json::parse(c.out);
  std::ifstream in(truth);
  const auto t = nlohmann::json::parse(in);
  for (const auto& [name, p] : fit["parameters"].items())
    z.push_back((p["value"].get<double>() - t["parameters"][name].get<double>()) / p["standard_error"].get<double>());
  return fit["poses"].size();
}

inline double rms(const std::vector<double>& z) {
  double sum = 0;
  for (double v : z) sum += v * v;
  return std::sqrt(sum / static_cast<double>(z.size()));
}

}  // namespace scalcal::testing
