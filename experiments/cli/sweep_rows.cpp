// The rows of a sweep as shown and saved (sweep_rows.hpp).
#include "experiments/cli/sweep_rows.hpp"

#include <iostream>

#include <fmt/format.h>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"

namespace scalcal::cli {
namespace {

std::string program_cell(const Program& p) {
  std::string s;
  for (std::size_t i = 0; i < p.positions.size(); ++i)
    s += fmt::format("{}{} {} {}", i ? ";" : "", p.positions[i](0), p.positions[i](1), p.positions[i](2));
  return s;
}

std::string number_or(const std::optional<double>& v, double scale, const char* format) {
  return v ? fmt::format(fmt::runtime(format), scale / *v) : std::string("n/a");
}

}  // namespace

RowSink::RowSink(const commands::Sweep& sweep, const commands::Values& v)
    : sweep_(sweep), json_(v.flag("--json")), timing_(!v.flag("--no-timing")) {
  if (v.given("--out")) {
    file_.emplace(v.text("--out"));
    file_->stream() << "criterion,positions,value,limit,ratio,starts,hits,distinct," << (timing_ ? "seconds," : "")
                    << "program\n";
    file_->flush();  // an unwritable file fails now, not after hours of work
  }
  if (!json_)
    std::cout << "crit   N            value        ratio   hits/starts  distinct" << (timing_ ? "  seconds" : "")
              << "\n";
}

void RowSink::add(const commands::SweepRow& row) {
  const SynthesisResult& r = row.result;
  const std::string name(criterion_name(row.task.criterion));
  if (sweep_.restricted() && progress_enabled() && announced_ != row.task.criterion)
    std::cerr << "the " << name << " limit on " << sweep_.region()->text() << "\n";
  announced_ = row.task.criterion;
  if (json_)
    all_.push_back(commands::to_json(sweep_, row, timing_));
  else
    std::cout << fmt::format("{:>4}{:>4}{:>17.10g}{:>13}{:>7}/{:<6}{:>9}", name, row.task.positions, r.value,
                             number_or(row.limit, r.value, "{:.8g}"), r.hits, r.starts, r.distinct)
              << (timing_ ? fmt::format("{:>9.3g}", r.seconds) : "") << std::endl;
  if (file_) {
    file_->stream() << fmt::format("{},{},{},{},{},{},{},{},", name, row.task.positions, r.value,
                                   row.limit ? fmt::format("{}", *row.limit) : "", number_or(row.limit, r.value, "{}"),
                                   r.starts, r.hits, r.distinct)
                    << (timing_ ? fmt::format("{},", r.seconds) : "") << '"' << program_cell(r.program) << "\"\n";
    file_->flush();
  }
}

void RowSink::close() {
  if (file_) file_->close();
  if (json_) print_json(all_);
}

}  // namespace scalcal::cli
