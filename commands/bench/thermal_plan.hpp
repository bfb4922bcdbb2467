// A thermal program's plan (issue 53): the rows grouped by set-point (to 0.5 degC, as the calibration groups
// an oven's poses), the set-points from the coldest (a board cold-soaked, then warmed, as PX4's and
// ArduPilot's thermal calibrations run), each set-point's positions in the bench's order (plan.hpp), and the
// time it takes: a soak per set-point, a rest per position, the axes' travel at the rehearsal's 45 deg/s.
#pragma once
#include <string>

#include "commands/bench/plan.hpp"

namespace scalcal::commands {

// The rehearsal's turning rate (numeric/thermal/thermal_rehearsal.hpp), which the time estimate assumes.
inline constexpr double kTravelDegPerSecond = 45;

// The temperatures of a program file's rows when it has a temperature column (t_c, temperature, temp, t);
// empty for a file without one or for a catalogue name.
std::vector<double> program_temperatures(const std::string& program);

// The plan of a request with temperatures (q.celsius): each set-point planned by plan() in turn.
PlanResult plan_thermal(const PlanRequest& q, const Progress& progress);

}  // namespace scalcal::commands
