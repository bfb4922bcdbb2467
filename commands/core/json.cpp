// The JSON helpers of every result (json.hpp).
#include "commands/core/json.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "numeric/io/input_error.hpp"

namespace scalcal::commands {

Json program_json(const Program& program) {
  Json list = Json::array();
  for (const auto& p : program.positions) list.push_back({p(0), p(1), p(2)});
  return list;
}

Json matrix_json(const Mat9& m) {
  Json rows = Json::array();
  for (int r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (int c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string json_text(const Json& j, int indent) { return j.dump(indent, ' ', false, Json::error_handler_t::replace); }

namespace {

// nlohmann's message with its "last read: '...'" excerpt cut to a readable length: a 70 MB file
// with one syntax error would otherwise put megabytes into a one-line message.
std::string short_message(const std::string& what) {
  const auto at = what.find("last read: '");
  if (at == std::string::npos || what.size() < 300) return what;
  const auto from = at + 12;
  const auto to = what.find("'", what.size() > 80 ? what.size() - 80 : from);
  const std::string excerpt = what.substr(from, std::min<std::size_t>(40, to == std::string::npos ? 40 : to - from));
  const auto tail = what.rfind(";");
  return what.substr(0, from) + excerpt + "...'" + (tail != std::string::npos && tail > from ? what.substr(tail) : "");
}

}  // namespace

Json parse_json_file_text(const std::string& text, const std::string& file, const std::string& expected) {
  // One set of keys per object being read: a key twice in one object is refused (the parser would
  // keep the last silently, and a file that says two things says nothing).
  std::vector<std::set<std::string>> keys;
  const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    const bool opens = event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start;
    // depth counts the containers around this event: an opening one is level depth + 1.
    if (depth + (opens ? 1 : 0) > kMaxJsonDepth)
      throw InputError(file, 0,
                       "not " + expected + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    if (event == Json::parse_event_t::object_start) keys.emplace_back();
    if (event == Json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == Json::parse_event_t::key && !keys.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!keys.back().insert(key).second)
        throw InputError(file, 0,
                         "not " + expected + ": the key \"" + display_name(key) + "\" appears twice in one object");
    }
    return true;
  };
  try {
    return Json::parse(text, check);
  } catch (const Json::exception& e) {  // a syntax error, or a number such as 1e400 out of range
    throw InputError(file, 0, "not " + expected + ": " + short_message(e.what()));
  }
}

}  // namespace scalcal::commands
