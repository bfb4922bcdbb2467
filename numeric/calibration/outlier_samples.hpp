// Single bad samples (a knock on the bench, a glitch in the log) inside otherwise good positions.
// One sample 10x off moves its position's mean far outside the linearised model and stops the
// iteration; the median of the position is not moved by it, so samples are judged against it.
#pragma once
#include <string>
#include <vector>

#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

struct ExcludedSample {
  int line = 0;         // line of the sample in its file (0 if not read from a file)
  int position = 0;     // index of its position in the data
  double distance = 0;  // |sample - position median| in robust scales
};

// A sample further than this many robust scales from its position's median is an outlier. The
// robust scale is the median of those distances over the file (1.54 sigma for Gaussian noise), so
// the cut is at about 15 sigma: never reached by Gaussian noise, always by a gross error.
inline constexpr double kOutlierScales = 10;

// Removes outlier samples from `data` in place and returns them, worst first. Only positions with
// at least 3 samples are judged, and a position where half of the samples or more lie
// beyond the cut is left whole: that is a noisy position, not a few bad samples, and the
// goodness-of-fit test is the right judge of it.
std::vector<ExcludedSample> exclude_outlier_samples(std::vector<PositionSamples>& data, double scales = kOutlierScales);

// "excluded 2 outlier samples (line, distance ...): line 9 (4.1e+03), line 40 (12.5); --keep-outliers keeps them"
std::string outlier_warning(const std::vector<ExcludedSample>& excluded);

}  // namespace scalcal
