// What a file scalcal writes says about its making: the tool's version and commit, and the time in
// UTC (SOURCE_DATE_EPOCH, when set, instead of the clock: the same inputs then give the same bytes).
#pragma once
#include <string>

namespace scalcal::commands {

std::string tool_version();  // "0.1"
std::string tool_commit();   // git describe at build time ("3f2c1a9b0d4e", "...-dirty"), or "unknown"
// "2024-05-01T12:34:56Z"; UsageError for a SOURCE_DATE_EPOCH that is not a decimal number of seconds
// from 0 to 253402300799 (the year 9999).
std::string utc_now_iso8601();
// The same check alone, for a front end to make before any work (UsageError).
void check_source_date_epoch();

}  // namespace scalcal::commands
