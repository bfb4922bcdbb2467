#include "numeric/calibration/data_checks.hpp"

#include <algorithm>
#include <sstream>

#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {

void check_calibration_data(const std::string& file, const std::vector<PositionSamples>& data, Modulus modulus,
                            double M) {
  const int n = static_cast<int>(data.size());
  if (n < kParameters)
    throw InputError(file, 0,
                     std::to_string(n) + " distinct positions; scalar calibration estimates " +
                         std::to_string(kParameters) + " parameters and needs at least " + std::to_string(kParameters) +
                         " positions");
  // The median, not the mean: a few bad positions must not hide (or fake) a units mistake.
  std::vector<double> ratio;
  for (const auto& p : data) ratio.push_back(p.mean().norm() / M);
  std::nth_element(ratio.begin(), ratio.begin() + n / 2, ratio.end());
  const double median = ratio[n / 2];
  if (median < 0.5 || median > 2.0) {
    std::ostringstream s;
    s << "the measured modulus is " << median << " times --magnitude " << M
      << "; the model needs it near 1 (wrong --magnitude or units?)";
    throw InputError(file, 0, s.str());
  }
  Program directions;
  directions.positions = position_directions(data, modulus);
  const Evaluation ev = evaluate(directions);
  if (!ev.full_rank()) throw InputError(file, 0, "the measured positions form a " + rank_deficiency(ev));
  if (ev.condition > kIllConditioned) throw InputError(file, 0, "the measured positions form an " + ill_conditioning(ev));
}

}  // namespace scalcal
