// Bench measurements from CSV: samples grouped by position (measurements_csv.hpp).
#include "numeric/calibration/measurements_csv.hpp"

#include <cmath>
#include <map>
#include <string>

#include "numeric/io/input_error.hpp"
#include "numeric/model/direction.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal {

std::vector<PositionSamples> measurements_from_table(const CsvTable& table, bool need_nominal) {
  for (const char* c : {"ix", "iy", "iz"})
    if (!table.has(c)) throw InputError(table.file, 1, std::string("missing column '") + c + "' (need ix,iy,iz)");
  const bool has_nominal = table.has("x") || table.has("y") || table.has("z");
  if (has_nominal || need_nominal)
    for (const char* c : {"x", "y", "z"})
      if (!table.has(c))
        throw InputError(table.file, 1,
                         std::string("missing column '") + c + "'" +
                             (need_nominal ? " (the projection modulus needs the nominal direction x,y,z)"
                                           : " (give all of x,y,z or none)"));
  const int ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  const int cp = table.column("position");
  const int cx = table.column("x"), cy = table.column("y"), cz = table.column("z");
  if (table.rows.empty()) throw InputError(table.file, 0, "no measurements after the header");

  std::vector<PositionSamples> out;
  std::vector<std::string> names;  // each position as the file names it, for messages
  std::map<std::string, std::size_t> index;
  const bool labelled = cp >= 0 && table.labels.size() == table.rows.size();
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    const auto& v = row.values;
    std::size_t k = out.size();
    if (cp >= 0) {
      const double p = v[cp];
      std::string key;
      if (labelled && std::isnan(p)) {  // a label such as P1: positions in order of first appearance
        key = "label " + table.labels[r];
      } else {
        if (p != std::floor(p) || std::abs(p) > 9e15)
          throw InputError(table.file, row.line,
                           "position must be an integer or a label such as P1, found " + std::to_string(p));
        key = std::to_string(static_cast<long long>(p));
      }
      const auto [it, fresh] = index.emplace(key, out.size());
      k = it->second;
      if (fresh) {
        out.emplace_back();
        names.push_back(key);
      }
    } else {
      out.emplace_back();
      names.push_back("");
    }
    if (out.size() > static_cast<std::size_t>(kMaximumPositions))
      throw InputError(table.file, row.line,
                       "more than the limit of " + std::to_string(kMaximumPositions) + " positions");
    PositionSamples& pos = out[k];
    if (pos.samples.empty()) pos.line = row.line;
    pos.samples.push_back(Vec3(v[ix], v[iy], v[iz]));
    pos.sample_lines.push_back(row.line);
    if (cx >= 0) {
      const Vec3 n(v[cx], v[cy], v[cz]);
      const std::optional<Vec3> unit = unit_direction(n);  // full precision from 1e-323 to 1e308
      if (!n.allFinite()) throw InputError(table.file, row.line, "a component of the nominal direction is not finite");
      if (!unit) throw InputError(table.file, row.line, "nominal direction x,y,z is the zero vector");
      const Vec3 u = *unit;
      if (!pos.nominal) {
        pos.nominal = u;
      } else if ((*pos.nominal - u).norm() > 1e-9) {
        throw InputError(table.file, row.line,
                         "nominal direction differs from that of line " + std::to_string(pos.line) +
                             " of the same position (" + names[k] + ")");
      }
    }
  }
  for (const auto& p : out)
    if (p.mean().norm() == 0.0)
      throw InputError(table.file, p.line, "the mean measurement of this position is the zero vector");
  return out;
}

std::vector<PositionSamples> read_measurements_csv(const std::string& path, bool need_nominal) {
  return measurements_from_table(read_csv(path), need_nominal);
}

}  // namespace scalcal
