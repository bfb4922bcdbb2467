// The one way calibration messages name the worst places in a file: " line 12 (41.2), line 30 (5.1)
// and 3 more". Used by the goodness-of-fit and the outlier-sample warnings.
#pragma once
#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace scalcal {

// `worst` holds (value, line) pairs, worst first; the first `shown` are listed, 3 significant digits.
inline std::string line_list(const std::vector<std::pair<double, int>>& worst, std::size_t shown = 8) {
  std::ostringstream s;
  s.precision(3);
  for (std::size_t i = 0; i < std::min(worst.size(), shown); ++i)
    s << (i ? "," : "") << " line " << worst[i].second << " (" << worst[i].first << ")";
  if (worst.size() > shown) s << " and " << worst.size() - shown << " more";
  return s.str();
}

}  // namespace scalcal
