// The JSON helpers of every result (json.hpp).
#include "commands/json.hpp"

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

}  // namespace scalcal::commands
