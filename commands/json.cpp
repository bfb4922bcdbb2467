// The JSON helpers of every result (json.hpp).
#include "commands/json.hpp"

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

Json parse_json_file_text(const std::string& text, const std::string& file, const std::string& expected) {
  const Json::parser_callback_t depth_check = [&](int depth, Json::parse_event_t, Json&) {
    if (depth > kMaxJsonDepth)
      throw InputError(file, 0,
                       "not " + expected + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  };
  try {
    return Json::parse(text, depth_check);
  } catch (const Json::exception& e) {  // a syntax error, or a number such as 1e400 out of range
    throw InputError(file, 0, "not " + expected + ": " + e.what());
  }
}

}  // namespace scalcal::commands
