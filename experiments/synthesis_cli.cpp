#include "experiments/synthesis_cli.hpp"

#include "numeric/io/input_error.hpp"
#include "numeric/io/program_csv.hpp"

namespace scalcal::cli {

CriterionKind criterion_option(Args& args, const std::string& fallback) {
  const std::string name = args.text("criterion", fallback);
  const auto c = parse_criterion(name);
  if (!c) throw UsageError("--criterion must be D, A, E or S, got '" + name + "'");
  return *c;
}

Json program_json(const Program& program) {
  Json list = Json::array();
  for (const auto& p : program.positions) {
    Json xyz = Json::array();
    for (int c = 0; c < 3; ++c) xyz.push(Json(p(c)));
    list.push(std::move(xyz));
  }
  return list;
}

void write_program_file(const std::string& path, const Program& program) {
  if (!write_program_csv(path, program)) throw InputError(path, 0, "cannot write the program file");
}

}  // namespace scalcal::cli
