#include "experiments/cli/json_output.hpp"

#include <iostream>

namespace scalcal::cli {

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

void print_json(const Json& j) { write_json(std::cout, j); }
// A string that is not valid UTF-8 (a file name in another encoding) is written with U+FFFD in
// place of its bad bytes, never an exception half-way through the output.
std::string json_text(const Json& j, int indent) { return j.dump(indent, ' ', false, Json::error_handler_t::replace); }

void write_json(std::ostream& out, const Json& j) { out << json_text(j, 2) << "\n"; }

}  // namespace scalcal::cli
