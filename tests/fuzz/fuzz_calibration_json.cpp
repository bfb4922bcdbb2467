// libFuzzer target: the calibration file `correct` and `export` read (the JSON `calibrate --out`
// writes), from text through the depth-limited parser to the correction it describes. Only
// InputError is an expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <string>

#include "commands/calibration/correct.hpp"
#include "commands/core/json.hpp"
#include "numeric/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const scalcal::commands::Json document = scalcal::commands::parse_json_file_text(text, "fuzz.json");
    for (const bool force : {false, true}) {
      scalcal::commands::Warnings warnings;
      (void)scalcal::commands::calibration_file_of(document, "fuzz.json", force, warnings);
    }
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
