// libFuzzer target: the program CSV reader (x,y,z or alpha1_deg,alpha2_deg) and what the CLI does
// next with a program it accepts (evaluate, write, read back). Only InputError is an expected
// outcome, as in the CLI (anything else would be an "internal error", exit 1); a crash, a hang, a
// sanitizer report or a failed round trip is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  scalcal::Program program;
  try {
    program = scalcal::program_from_table(scalcal::parse_csv(text, "fuzz.csv"));
  } catch (const scalcal::InputError&) {
    return 0;
  }
  (void)scalcal::evaluate(program);
  // What scalcal writes it must read back: the same unit vectors to the last few bits.
  std::ostringstream out;
  scalcal::write_program_csv(out, program);
  const scalcal::Program back = scalcal::program_from_table(scalcal::parse_csv(out.str(), "roundtrip.csv"));
  if (back.size() != program.size()) std::abort();
  for (int i = 0; i < program.size(); ++i)
    if ((back.positions[i] - program.positions[i]).norm() > 1e-12) std::abort();
  return 0;
}
