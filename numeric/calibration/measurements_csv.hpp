// Bench measurements as CSV: columns ix,iy,iz (measured projections, required), position (an
// integer or a text label such as P1; rows sharing it are samples of one position, optional),
// x,y,z (the nominal direction, required for the projection modulus). Read into positions in
// order of first appearance.
#pragma once
#include <string>
#include <vector>

#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/io/csv_table.hpp"

namespace scalcal {

// Throws InputError (file, line, reason) for a bad file, a missing column, a position that is a
// non-integer number, a zero nominal direction, or samples of one position with different nominals.
std::vector<PositionSamples> read_measurements_csv(const std::string& path, bool need_nominal);
std::vector<PositionSamples> measurements_from_table(const CsvTable& table, bool need_nominal);

}  // namespace scalcal
