// libFuzzer target: the bench measurement CSV reader (ix,iy,iz [,position] [,x,y,z]) and the whole
// calibrate path after it: outlier samples, the data checks, the estimator and the goodness of fit.
// The first byte picks the modulus. Only InputError is an expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <string>

#include "numeric/calibration/data_checks.hpp"
#include "numeric/calibration/goodness_of_fit.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/measurements_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const scalcal::Modulus modulus = data[0] & 1 ? scalcal::Modulus::projection : scalcal::Modulus::norm;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    auto samples =
        scalcal::measurements_from_table(scalcal::parse_csv(text, "fuzz.csv"), modulus == scalcal::Modulus::projection);
    (void)scalcal::exclude_outlier_samples(samples);
    scalcal::check_calibration_data("fuzz.csv", samples, modulus, 1.0);
    scalcal::CalibrationOptions options;
    options.modulus = modulus;
    const auto result = scalcal::calibrate(samples, options);
    (void)scalcal::goodness_of_fit(samples, result, modulus, 1.0);
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
