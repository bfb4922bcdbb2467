// The --region option shared by the commands that design or judge a program for a restricted
// bench: repeatable (the union), parsed and checked for identifiability before any work starts.
#pragma once
#include <string>
#include <vector>

#include "numeric/io/program_csv.hpp"
#include "numeric/region/region.hpp"

namespace CLI {
class App;
}

namespace scalcal::cli {

void add_region_option(CLI::App& app, std::vector<std::string>& specs);

// The region of the specs (the sphere when there are none). Throws InputError (exit 2) for a bad
// spec, a region on which no program is rank 9, or one whose conditioning is beyond double
// precision; warns on stderr, naming the command, when the region's best conditioning is poor.
Region resolve_region(const std::vector<std::string>& specs, const std::string& command);

// For a region of one cap or band: the columns tilt_deg (from its axis) and azimuth_deg (in its
// azimuth_frame) of each position, for --out; none otherwise.
std::vector<ExtraColumn> region_columns(const Region& region, const Program& program);

}  // namespace scalcal::cli
