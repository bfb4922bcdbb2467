// Reading, writing and building thermal programs (thermal_program.hpp).
#include "numeric/thermal/thermal_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {

ThermalProgram read_thermal_program_csv(const std::string& path) {
  const CsvTable t = read_csv(path);
  const int x = t.column("x"), y = t.column("y"), z = t.column("z");
  int temp = -1;
  for (const std::string& name : kTemperatureColumns)
    if (temp < 0) temp = t.column(name);
  if (x < 0 || y < 0 || z < 0 || temp < 0)
    throw InputError(path, 0,
                     "a thermal program needs columns x,y,z and a temperature column (t_c, temperature, temp or t)");
  ThermalProgram p;
  for (const CsvTable::Row& row : t.rows) {
    const Eigen::Vector3d v(row.values[static_cast<std::size_t>(x)], row.values[static_cast<std::size_t>(y)],
                            row.values[static_cast<std::size_t>(z)]);
    if (!(v.norm() > 0)) throw InputError(path, row.line, "the position is the zero vector");
    const double c = row.values[static_cast<std::size_t>(temp)];
    if (c < -273.15 || c > 1000)
      throw InputError(path, row.line,
                       "temperature " + std::to_string(c) + " degrees Celsius is outside -273.15..1000");
    p.positions.push_back(v.normalized());
    p.celsius.push_back(c);
  }
  return p;
}

void write_thermal_program_csv(std::ostream& out, const ThermalProgram& p) {
  out << "x,y,z,t_c\n";
  char buffer[128];
  for (int i = 0; i < p.size(); ++i) {
    const auto& e = p.positions[static_cast<std::size_t>(i)];
    std::snprintf(buffer, sizeof buffer, "%.17g,%.17g,%.17g,%.17g\n", e(0), e(1), e(2),
                  p.celsius[static_cast<std::size_t>(i)]);
    out << buffer;
  }
}

Eigen::MatrixXd thermal_information(const ThermalModel& model, const TemperatureRange& range, const ThermalProgram& p) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(model.parameters(), model.parameters());
  for (int i = 0; i < p.size(); ++i) {
    const Eigen::VectorXd h =
        model.row(p.positions[static_cast<std::size_t>(i)], range.tau(p.celsius[static_cast<std::size_t>(i)]));
    m.selfadjointView<Eigen::Lower>().rankUpdate(h);
  }
  m = m.selfadjointView<Eigen::Lower>();
  return m / std::max(1, p.size());
}

std::vector<int> efficient_rounding(const std::vector<double>& w, int total) {
  const double l = static_cast<double>(w.size());
  std::vector<int> n;
  for (double wi : w) n.push_back(static_cast<int>(std::ceil((total - l / 2) * wi - 1e-12)));
  auto sum = [&] {
    int s = 0;
    for (int v : n) s += v;
    return s;
  };
  while (sum() < total) {  // the one whose count is smallest for its weight gains
    std::size_t j = 0;
    for (std::size_t i = 1; i < n.size(); ++i)
      if (n[i] / w[i] < n[j] / w[j]) j = i;
    ++n[j];
  }
  while (sum() > total) {  // the one whose count is largest for its weight loses
    std::size_t j = 0;
    for (std::size_t i = 1; i < n.size(); ++i)
      if ((n[i] - 1) / w[i] > (n[j] - 1) / w[j]) j = i;
    --n[j];
  }
  return n;
}

ThermalProgram product_program(const std::vector<Eigen::Vector3d>& sphere, const IntervalDesign& design,
                               const std::vector<int>& counts, const TemperatureRange& range) {
  ThermalProgram p;
  for (std::size_t i = 0; i < design.points.size(); ++i)
    for (int copy = 0; copy < counts[i]; ++copy)
      for (const auto& e : sphere) {
        p.positions.push_back(e);
        p.celsius.push_back(range.celsius(design.points[i]));
      }
  return p;
}

}  // namespace scalcal
