// Programs as CSV files: read with columns x,y,z (normalised on reading) or
// alpha1_deg,alpha2_deg (azimuth, elevation); written with x,y,z,alpha1_deg,alpha2_deg.
#pragma once
#include <ostream>
#include <string>

#include "numeric/io/csv_table.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

inline constexpr int kMinimumPositions = 9;
// The most positions a program may have (files, catalogue names, random-N): the criteria cost
// O(N) and any optimum needs far fewer; the limit keeps a typo from allocating gigabytes.
inline constexpr int kMaximumPositions = 100000;

// Throws InputError for a bad file, a zero vector, fewer than 9 or more than 100000 positions.
Program read_program_csv(const std::string& path);
Program program_from_table(const CsvTable& table);

// A column written after x,y,z,alpha1_deg,alpha2_deg: its name and one value per position.
struct ExtraColumn {
  std::string name;
  std::vector<double> values;
};

// Numbers are written as the shortest text that reads back to the same double. The path form
// returns false when the file could not be opened, written or closed (e.g. a full disk).
void write_program_csv(std::ostream& out, const Program& program, const std::vector<ExtraColumn>& extra = {});
bool write_program_csv(const std::string& path, const Program& program);

// Azimuth alpha1 and elevation alpha2 in degrees of a unit vector (inverse of from_angles_deg).
Eigen::Vector2d angles_deg(const Vec3& eta);

}  // namespace scalcal
