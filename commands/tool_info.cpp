// The tool's version, commit and the time (tool_info.hpp).
#include "commands/tool_info.hpp"

#include <cstdlib>
#include <ctime>

#include "tool_commit.hpp"

namespace scalcal::commands {

std::string tool_version() { return SCALCAL_TOOL_VERSION; }
std::string tool_commit() { return SCALCAL_COMMIT; }

std::string utc_now_iso8601() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && v >= 0) now = static_cast<std::time_t>(v);
  }
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace scalcal::commands
