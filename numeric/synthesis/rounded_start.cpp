// The efficient rounding of a model's stated optimal measure (rounded_start.hpp).
#include "numeric/synthesis/rounded_start.hpp"

#include <cmath>
#include <vector>

namespace scalcal {

std::optional<Program> rounded_limit_measure(ModelKind model, std::string_view criterion, int positions) {
  const std::optional<ModelLimit> limit = stated_limit(model, criterion);
  if (!limit || !(limit->axis_weight >= 0 && limit->axis_weight <= 1) || positions < 1) return std::nullopt;
  // Antipodal pairs and the weight of each: 3 axis pairs, then 4 diagonal pairs.
  const double s = 1 / std::sqrt(3.0);
  const std::vector<Vec3> pairs = {Vec3(1, 0, 0),  Vec3(0, 1, 0),  Vec3(0, 0, 1), Vec3(s, s, s),
                                   Vec3(s, s, -s), Vec3(s, -s, s), Vec3(-s, s, s)};
  std::vector<double> weight(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i)
    weight[i] = i < 3 ? limit->axis_weight / 3 : (1 - limit->axis_weight) / 4;
  // Efficient rounding of the pairs' weights to M = N / 2 pairs: m_i = ceil((M - l / 2) w_i) over the l
  // pairs of positive weight, then one at a time up where m_i / w_i is least (or down where
  // (m_i - 1) / w_i is largest) until they sum to M; the first pair wins a tie.
  const int M = positions / 2;
  int l = 0;
  for (double w : weight) l += w > 0;
  std::vector<int> m(pairs.size(), 0);
  int total = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (weight[i] > 0) total += m[i] = std::max(0, static_cast<int>(std::ceil((M - 0.5 * l) * weight[i])));
  while (total != M) {
    const bool up = total < M;
    std::size_t best = pairs.size();
    double best_key = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      if (!(weight[i] > 0) || (!up && m[i] == 0)) continue;
      const double key = (up ? m[i] : m[i] - 1) / weight[i];
      if (best == pairs.size() || (up ? key < best_key : key > best_key)) {
        best = i;
        best_key = key;
      }
    }
    if (best == pairs.size()) return std::nullopt;
    m[best] += up ? 1 : -1;
    total += up ? 1 : -1;
  }
  Program out;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (int k = 0; k < m[i]; ++k) {
      out.positions.push_back(pairs[i]);
      out.positions.push_back(-pairs[i]);
    }
  // An odd N: one more position on the first pair of largest weight.
  if (positions % 2 == 1) {
    std::size_t top = 0;
    for (std::size_t i = 1; i < pairs.size(); ++i)
      if (weight[i] > weight[top]) top = i;
    out.positions.push_back(pairs[top]);
  }
  return out;
}

}  // namespace scalcal
