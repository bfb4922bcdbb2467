// The tool's version, commit and the time (tool_info.hpp).
#include "commands/core/tool_info.hpp"

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <string>

#include "commands/core/usage_error.hpp"
#include "numeric/io/input_error.hpp"

#include "tool_commit.hpp"

namespace scalcal::commands {

std::string tool_version() { return SCALCAL_TOOL_VERSION; }
std::string tool_commit() { return SCALCAL_COMMIT; }

namespace {

// The last second a four-digit year holds: 9999-12-31T23:59:59Z.
constexpr long long kLastSecond = 253402300799LL;

// SOURCE_DATE_EPOCH as the reproducible-builds specification has it: the seconds since
// 1970-01-01T00:00:00Z as a decimal integer; a value that does not parse is an error, not a value
// ignored for the clock (the date would then change from run to run unnoticed).
std::time_t source_date_epoch(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 12 &&
                      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  const long long v = digits ? std::stoll(text) : -1;
  if (v < 0 || v > kLastSecond)
    throw UsageError("SOURCE_DATE_EPOCH='" + display_name(text.substr(0, 40)) +
                     "' is not a whole number of seconds since 1970-01-01 from 0 to " + std::to_string(kLastSecond) +
                     " (9999-12-31T23:59:59Z)");
  return static_cast<std::time_t>(v);
}

}  // namespace

void check_source_date_epoch() {
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch && *epoch) source_date_epoch(epoch);
}

std::string utc_now_iso8601() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  const std::time_t now = epoch && *epoch ? source_date_epoch(epoch) : std::time(nullptr);  // set but empty: unset
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace scalcal::commands
