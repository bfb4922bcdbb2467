// `scalcal calibrate --measurements LOG --model BASE+Tk --magnitude M [--temperature T1..T2]`: a
// thermal log (a raw log with a temperature column: temp, temperature or t_c, any case) calibrated
// under a thermal model: still poses found as for any log, each with its mean temperature, then
// numeric/thermal/thermal_calibration.hpp's fit. Each coefficient with its standard error, in tau's
// and in degrees Celsius about the range's middle; the residual of each pose against its temperature.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/warning.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/thermal/thermal_calibration.hpp"

namespace scalcal::commands {

struct ThermalCalibration {
  std::string file;
  std::string temperature_column;  // as the file spells it
  std::vector<ThermalPose> poses;
  ThermalFit fit;
  Warnings warnings;
};

// The log's temperature column's index in `table` (temp, temperature, t_c, any case), or -1.
int temperature_column(const CsvTable& table);

// Throws InputError for a log without a temperature column or without poses, and for a fit whose
// poses cannot identify the model (fit.problem); returns a fit that did not converge with its problem set.
ThermalCalibration calibrate_thermal(const std::string& file, const CsvTable& table, const ThermalModel& model,
                                     const std::optional<TemperatureRange>& range, double magnitude,
                                     const StaticIntervalOptions& intervals);

Json to_json(const ThermalCalibration& c);

// The keys a thermal fit and a thermal rehearsal's truth share: model, temperature_c, reference_c, half_range_c.
Json thermal_model_json(const ThermalModel& model, const TemperatureRange& range);

}  // namespace scalcal::commands
