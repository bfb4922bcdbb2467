// Programs as CSV files: read with columns x,y,z (normalised on reading) or
// alpha1_deg,alpha2_deg (azimuth, elevation); written with x,y,z,alpha1_deg,alpha2_deg. A program
// may carry the bench's region as a comment line `# region: SPEC;SPEC` (the --region specs of
// optimize, plan and evaluate), so the commands that read it judge it on that region.
#pragma once
#include <ostream>
#include <string>

#include "numeric/io/csv_table.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

// The fewest positions any registered model can use (bias3's 3 parameters); a command checks its
// own model's minimum where the model is known (commands::program_of).
inline constexpr int kMinimumPositions = 3;
// The most positions a program may have (files, catalogue names, random-N): the criteria cost
// O(N) and any optimum needs far fewer; the limit keeps a typo from allocating gigabytes.
inline constexpr int kMaximumPositions = 100000;

// Throws InputError for a bad file, a zero vector, fewer than 3 or more than 100000 positions.
Program read_program_csv(const std::string& path);
Program program_from_table(const CsvTable& table);

// A column written after x,y,z,alpha1_deg,alpha2_deg: its name and one value per position.
struct ExtraColumn {
  std::string name;
  std::vector<double> values;
};

// What a program file says beside its positions: the region (written first as `# region: A;B`),
// then other comment lines (without their '#').
struct ProgramNotes {
  std::vector<std::string> region;
  std::vector<std::string> comments;
};

// Numbers are written as the shortest text that reads back to the same double. The path form
// returns false when the file could not be opened, written or closed (e.g. a full disk).
void write_program_csv(std::ostream& out, const Program& program, const std::vector<ExtraColumn>& extra = {},
                       const ProgramNotes& notes = {});
bool write_program_csv(const std::string& path, const Program& program);

// The `# region: A;B` line of these specs (with its newline). A spec is written as it is unless it
// holds ';', '"', a backslash, a control character or a space at either end (a `candidates:` path
// may): then it is quoted, "..." with \" \\ \n \r \t and \xHH, so the line reads back as these specs.
std::string region_line(const std::vector<std::string>& specs);

// The region a program file's text carries: the specs of its first `# region:` line (split at ';',
// quoted specs unquoted) and that line's number; no specs when it has none. InputError for a quoted
// spec that does not end or an escape that is not one of region_line's.
struct ProgramRegion {
  std::vector<std::string> specs;
  int line = 0;
};
ProgramRegion program_region(const std::string& text);
// The same read from a file (InputError when it cannot be read).
ProgramRegion read_program_region(const std::string& path);

// Azimuth alpha1 and elevation alpha2 in degrees of a unit vector (inverse of from_angles_deg).
Eigen::Vector2d angles_deg(const Vec3& eta);

}  // namespace scalcal
