// The region of a request's --region specs, checked before any work starts: parsed, identifiable,
// and within what double precision resolves. Shared by every command that designs or judges a
// program for a restricted bench.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "commands/core/usage_error.hpp"
#include "commands/core/warning.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region.hpp"

namespace scalcal::commands {

// Above this condition number of the region's uniform measure, K is not resolved in double
// precision (a cap of 3 degrees: 7.9e14; of 4 degrees: 7.9e13).
inline constexpr double kBeyondDouble = 1e14;

// The region of the specs (the sphere when there are none). Throws InputError (exit 2) for a bad
// spec, a region on which no program is rank 9, or one whose conditioning is beyond double
// precision; adds a warning when the region's best conditioning is poor.
Region resolve_region(const std::vector<std::string>& specs, Warnings& warnings);

// The conditioning check of resolve_region for a region made otherwise (optimize --margin's inset
// one): InputError naming `option` beyond double precision, a warning when poor.
void check_conditioning(const Region& region, Warnings& warnings, const std::string& option);

// True when the specs name the whole sphere (none, or only "sphere").
bool is_sphere(const std::vector<std::string>& specs);

// The refusal of a restricted region under a model without region limits, one sentence for every command:
// "COMMAND: --region has limits for the paper9 model only (got --model axis6)".
UsageError region_limits_refusal(std::string_view command, std::string_view model);

// The specs as a program file's region line holds them ("cap:90;cap:30:x"), for messages.
std::string specs_text(const std::vector<std::string>& specs);

// For a region of one cap or band: the columns tilt_deg (from its axis) and azimuth_deg (in its
// azimuth_frame) of each position, for a program file; none otherwise.
std::vector<ExtraColumn> region_columns(const Region& region, const Program& program);

// How far outside the region a position may lie and still count as inside when a command judges a
// program (evaluate, calibrate: --tolerance): a bench set to 0.1 degrees puts a position designed on
// a cap's rim up to 0.05 degrees beyond it.
inline constexpr double kDefaultToleranceDeg = 0.05;

// Throws InputError naming up to ten positions outside the region by more than tolerance_deg
// (1-based, with their tilt from the nearest zone's axis when the region has zones).
void refuse_outside(const std::string& name, const Program& program, const Region& region,
                    double tolerance_deg = kRegionToleranceDeg);

// The region specs a command judges PROGRAM on: `given` (--region) when there are any, else the
// `# region:` line of the program file (none for a catalogue name or data), its relative
// `candidates:` paths taken from the file's folder. A bad region line is an InputError naming the
// file and line; a file's region that --region replaces is a warning.
std::vector<std::string> regions_for(const std::vector<std::string>& given, const std::string& program_argument,
                                     Warnings& warnings);

// The specs as a file written to `file` must carry them to read back from anywhere: a relative
// `candidates:` path (relative to the working folder) made relative to the file's folder, or
// absolute for standard output ("-") or when no relative path leads there.
std::vector<std::string> specs_written_to(const std::vector<std::string>& specs, const std::string& file);

}  // namespace scalcal::commands
