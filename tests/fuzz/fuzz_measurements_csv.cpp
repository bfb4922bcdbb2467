// libFuzzer target: the bench measurement CSV reader (ix,iy,iz [,position] [,x,y,z]) and the raw log
// reader (t,ix,iy,iz as CSV or whitespace text), and the whole calibrate path after them: static
// intervals, outlier samples, the data checks, the start in any units, the estimator and the
// goodness of fit. The first byte picks the modulus (bit 0), a raw log (bit 1) and the magnitude
// (bit 2: 1, else auto); for a raw log, the stream's chunk (bits 3-5: 1 to 22 rows), the floor (bit 6:
// the log's quiet windows, else a still start) and the adaptive choice's detectors (bit 7), the poses
// asked for after every chunk. Only InputError is an expected outcome, as in the CLI.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/calibration_stream.hpp"
#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const scalcal::Modulus modulus = data[0] & 1 ? scalcal::Modulus::projection : scalcal::Modulus::norm;
  const bool raw = data[0] & 2;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    std::vector<scalcal::PositionSamples> samples;
    if (raw) {
      const scalcal::RawLog log = scalcal::parse_raw_log(text, "fuzz.txt");
      scalcal::StaticIntervalOptions o;  // short enough for the small logs a fuzzer writes
      if (!(data[0] & 64)) o.still_seconds = 0.5;
      o.window_seconds = 0.05;
      o.min_seconds = 0.05;
      const int chunk = 1 + ((data[0] >> 3) & 7) * 3;
      scalcal::CalibrationStream stream(log.file, o, data[0] & 128);
      for (int b = 0; b < log.size(); b += chunk) {
        scalcal::RawLog part;
        part.file = log.file;
        const int e = std::min(log.size(), b + chunk);
        part.t.assign(log.t.begin() + b, log.t.begin() + e);
        part.samples.assign(log.samples.begin() + b, log.samples.begin() + e);
        part.lines.assign(log.lines.begin() + b, log.lines.begin() + e);
        stream.add(part, e == log.size());
        (void)stream.pose_sums();
      }
      samples = stream.positions();
    } else {
      samples = scalcal::measurements_from_table(scalcal::parse_csv(text, "fuzz.csv"),
                                                 modulus == scalcal::Modulus::projection);
    }
    (void)scalcal::exclude_outlier_samples(samples);
    scalcal::AnyUnitsOptions options;
    options.modulus = raw ? scalcal::Modulus::norm : modulus;
    options.magnitude_auto = !(data[0] & 4);
    options.weight_by_samples = !raw;
    const auto result = scalcal::calibrate_any_units("fuzz", samples, options);
    (void)result.chi_square;
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
