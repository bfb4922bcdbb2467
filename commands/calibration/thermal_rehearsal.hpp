// `scalcal simulate --program THERMAL.csv --model BASE+Tk --temperature T1..T2 --log FILE [--truth FILE]`:
// a thermal rehearsal (numeric/thermal/thermal_rehearsal.hpp) as the CLI and the Python module write it:
// the raw log with columns t,ix,iy,iz,temp and the truth in calibrate's thermal JSON keys.
#pragma once
#include <optional>
#include <ostream>

#include "commands/core/json.hpp"
#include "commands/core/values.hpp"
#include "numeric/thermal/thermal_rehearsal.hpp"

namespace scalcal::commands {

// The request when --model names a thermal model (nullopt otherwise); UsageError for what it lacks.
std::optional<ThermalRehearsalRequest> thermal_rehearsal_request(const Values& v);

void write_thermal_log(std::ostream& out, const ThermalRehearsalRequest& q, const ThermalRehearsal& r);
Json thermal_truth_json(const ThermalRehearsalRequest& q, const ThermalRehearsal& r);

}  // namespace scalcal::commands
