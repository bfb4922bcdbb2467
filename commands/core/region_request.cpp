// Regions of requests (region_request.hpp).
#include "commands/core/region_request.hpp"

#include <cstdio>
#include <filesystem>

#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::commands {
namespace {

std::string short_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

bool is_sphere(const std::vector<std::string>& specs) {
  return specs.empty() || (specs.size() == 1 && specs[0] == "sphere");
}

UsageError region_limits_refusal(std::string_view command, std::string_view model) {
  return UsageError(std::string(command) + words(": {region} has limits for the ") +
                    models_supporting(ModelCapability::region_limits) + words(" model only (got {model} ") +
                    std::string(model) + ")");
}

std::string specs_text(const std::vector<std::string>& specs) {
  std::string text;
  for (const auto& s : specs) text += (text.empty() ? "" : ";") + s;
  return text;
}

void check_conditioning(const Region& region, Warnings& warnings, const std::string& option) {
  double condition = 0;
  try {
    condition = check_region_identifiable(region);
  } catch (const InputError& e) {  // named by the option that made the region
    throw InputError(option, e.line(), e.reason());
  }
  if (condition > kBeyondDouble)
    throw InputError(option, 0,
                     "'" + region.text() + "': even the uniform measure has condition number " +
                         short_number(condition) +
                         ", beyond what double precision resolves (1e14): bias and scale factor are confounded "
                         "there (a cap narrower than about 4 degrees)");
  if (condition > kIllConditioned)
    warnings.push_back({"", "on " + region.text() + " even the uniform measure has condition number " +
                                short_number(condition) + " (bias and scale factor are nearly confounded there)"});
}

Region resolve_region(const std::vector<std::string>& specs, Warnings& warnings) {
  Region region = parse_region(specs);
  check_conditioning(region, warnings, "--region");
  return region;
}

std::vector<ExtraColumn> region_columns(const Region& region, const Program& program) {
  if (region.zones.size() != 1 || !region.candidates.empty() || region.is_sphere()) return {};
  const Zone& zone = region.zones.front();
  ExtraColumn tilt{"tilt_deg", {}}, azimuth{"azimuth_deg", {}};
  for (const Vec3& x : program.positions) {
    tilt.values.push_back(zone.tilt_deg(x));
    // -180..180, the range of alpha1_deg beside it in the same file (and of a plan's azimuths).
    const double a = azimuth_deg(zone, x);
    azimuth.values.push_back(a > 180 ? a - 360 : a);
  }
  return {tilt, azimuth};
}

void refuse_outside(const std::string& name, const Program& program, const Region& region, double tolerance_deg) {
  std::vector<int> outside;
  for (int i = 0; i < program.size(); ++i)
    if (!region.contains(program.positions[static_cast<std::size_t>(i)], tolerance_deg)) outside.push_back(i);
  if (outside.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < outside.size() && k < 10; ++k) {
    const int i = outside[k];
    list += (k ? ", " : "") + std::to_string(i + 1);
    if (!region.zones.empty()) {
      char tilt[32];
      std::snprintf(tilt, sizeof tilt, "%.4g",
                    region.zones.front().tilt_deg(program.positions[static_cast<std::size_t>(i)]));
      list += std::string(" (tilt ") + tilt + " deg)";
    }
  }
  if (outside.size() > 10) list += ", ...";
  throw InputError(name, 0,
                   std::to_string(outside.size()) + " of " + std::to_string(program.size()) +
                       " positions are outside the region " + region.text() + ": position " + list);
}

namespace {

constexpr std::string_view kCandidates = "candidates:";

// A relative candidates path of a file in `folder`, as the working folder sees it.
std::vector<std::string> specs_read_from(std::vector<std::string> specs, const std::filesystem::path& folder) {
  if (folder.empty()) return specs;
  for (auto& s : specs)
    if (s.starts_with(kCandidates)) {
      const std::filesystem::path p(s.substr(kCandidates.size()));
      if (!p.empty() && p.is_relative()) s = std::string(kCandidates) + (folder / p).lexically_normal().string();
    }
  return specs;
}

}  // namespace

std::vector<std::string> specs_written_to(const std::vector<std::string>& specs, const std::string& file) {
  namespace fs = std::filesystem;
  std::vector<std::string> out = specs;
  for (auto& s : out) {
    if (!s.starts_with(kCandidates)) continue;
    const fs::path p(s.substr(kCandidates.size()));
    if (p.empty() || p.is_absolute()) continue;
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec).lexically_normal();
    if (ec) continue;
    fs::path written = absolute;
    if (file != "-") {
      const fs::path folder = fs::absolute(fs::path(file).parent_path(), ec).lexically_normal();
      const fs::path relative = ec ? fs::path() : absolute.lexically_relative(folder);
      if (!relative.empty()) written = relative;
    }
    s = std::string(kCandidates) + written.string();
  }
  return out;
}

std::vector<std::string> regions_for(const std::vector<std::string>& given, const std::string& program_argument,
                                     Warnings& warnings) {
  if (program_argument.empty() || named_program(program_argument)) return given;
  std::error_code ec;
  if (program_argument != "-" && !std::filesystem::is_regular_file(program_argument, ec)) return given;
  ProgramRegion file = read_program_region(program_argument);
  if (program_argument != "-")
    file.specs = specs_read_from(file.specs, std::filesystem::path(program_argument).parent_path());
  if (file.specs.empty()) return given;
  try {
    parse_region(file.specs);
  } catch (const InputError& e) {
    throw InputError(program_argument, file.line, "# region: " + e.reason());
  }
  if (given.empty()) return file.specs;
  if (given != file.specs) {
    warnings.push_back({program_argument, "the program's region " + specs_text(file.specs) + " (line " +
                                              std::to_string(file.line) + words(") is replaced by {region}")});
  }
  return given;
}

}  // namespace scalcal::commands
