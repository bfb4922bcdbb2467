// --instrument gyro on the design commands (limits, optimize): a bench that reaches the table-axis
// directions R on a rate table measures R and -R, a turn reversed being the antipodal position
// (proofs/gyro_rate_table.md, Theorem 24), so the accelerometer's region R becomes R u (-R).
#pragma once
#include <string>
#include <vector>

#include "commands/core/values.hpp"

namespace scalcal::commands {

// The --instrument option (accel, gyro), shared by limits and optimize.
Option design_instrument_option();

// The specs of R u (-R): each cap and band with its axis reversed beside it; sphere and faces are
// their own antipodes. UsageError for candidates:FILE (list both directions of each candidate in the
// file instead) and a spec that cannot be read (add_region_spec then names it).
std::vector<std::string> with_reversed_turns(const std::vector<std::string>& specs);

// The specs as the instrument sees them: unchanged for accel.
std::vector<std::string> instrument_regions(const Values& values, const std::vector<std::string>& specs);

}  // namespace scalcal::commands
