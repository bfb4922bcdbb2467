// A thermal calibration program: N rows, each a position (unit vector eta) and the temperature it is
// measured at (degrees Celsius). Read from CSV with columns x,y,z and a temperature column (t, temp,
// temperature or t_c, any case); written with x,y,z,t_c. A product program puts every position of a
// sphere program at every set-point, the set-points' counts rounded from their optimal weights.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/thermal/interval_design.hpp"
#include "numeric/thermal/temperature_range.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal {

struct ThermalProgram {
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> celsius;
  int size() const { return static_cast<int>(positions.size()); }
};

// The temperature column's accepted names, in the order they are looked for.
inline const std::vector<std::string> kTemperatureColumns = {"t_c", "temperature", "temp", "t"};

// Throws InputError (file, line, reason) for a bad file, a missing temperature column, a zero vector.
ThermalProgram read_thermal_program_csv(const std::string& path);
void write_thermal_program_csv(std::ostream& out, const ThermalProgram& program);

// sum_i row_i row_i^T / N under the model, temperatures normalised by the range (which need not
// contain them: a set-point outside it is extrapolation, and the caller warns).
Eigen::MatrixXd thermal_information(const ThermalModel& model, const TemperatureRange& range,
                                    const ThermalProgram& program);

// Counts n_i summing to `total` from weights w_i by Pukelsheim and Rieder's efficient rounding.
std::vector<int> efficient_rounding(const std::vector<double>& weights, int total);

// Each position of `sphere` at each set-point of `design`, repeated counts[i] times at set-point i,
// set-points in increasing temperature (the order an oven reaches them), positions in their order.
ThermalProgram product_program(const std::vector<Eigen::Vector3d>& sphere, const IntervalDesign& design,
                               const std::vector<int>& counts, const TemperatureRange& range);

}  // namespace scalcal
