// The efficient rounding of a model's stated optimal measure (rounded_start.hpp).
#include "numeric/synthesis/rounded_start.hpp"

#include <cmath>
#include <random>
#include <utility>
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

bool asks_for_rounding_starts(ModelKind model, std::string_view criterion) {
  const std::optional<ModelLimit> limit = stated_limit(model, criterion);
  return limit && limit->rounding_starts && limit->axis_weight >= 0 && limit->axis_weight <= 1;
}

std::optional<Program> randomised_rounding(ModelKind model, std::string_view criterion, int positions,
                                           std::uint64_t seed) {
  if (!asks_for_rounding_starts(model, criterion) || positions < 1) return std::nullopt;
  const ModelLimit limit = *stated_limit(model, criterion);
  // The 6 axis directions, then the 8 cube diagonals, with N times their weight.
  std::vector<Vec3> directions;
  std::vector<double> target;
  for (int a = 0; a < 3; ++a)
    for (double sign : {1.0, -1.0}) {
      directions.push_back(sign * Vec3::Unit(a));
      target.push_back(positions * limit.axis_weight / 6);
    }
  for (double x : {1.0, -1.0})
    for (double y : {1.0, -1.0})
      for (double z : {1.0, -1.0}) {
        directions.push_back(Vec3(x, y, z).normalized());
        target.push_back(positions * (1 - limit.axis_weight) / 8);
      }
  // Uniform numbers and the shuffle from the engine's bits alone (no library distribution), so the
  // program is the same under every standard library.
  std::mt19937_64 engine(seed);
  const auto uniform = [&engine] { return static_cast<double>(engine() >> 11) * 0x1.0p-53; };
  const std::size_t n = directions.size();
  std::vector<int> count(n);
  std::vector<double> fraction(n);
  int total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    count[i] = static_cast<int>(std::floor(target[i]));
    total += count[i];
    fraction[i] = target[i] - count[i];
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  for (std::size_t i = n - 1; i > 0; --i) std::swap(order[i], order[static_cast<std::size_t>(engine() % (i + 1))]);
  // Systematic sampling: the remaining N - sum floor positions go one per unit the running sum of the
  // fractions crosses, from a random offset in [0, 1).
  double running = uniform();
  for (std::size_t j = 0; j < n && total < positions; ++j) {
    running += fraction[order[j]];
    while (running >= 1 && total < positions) {
      ++count[order[j]];
      ++total;
      running -= 1;
    }
  }
  for (std::size_t j = 0; total < positions; j = (j + 1) % n) {  // rounding left one short
    ++count[order[j]];
    ++total;
  }
  Program out;
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < count[i]; ++k) {
      const Vec3 jitter(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5);
      out.positions.push_back((directions[i] + 1e-3 * jitter).normalized());
    }
  return out;
}

}  // namespace scalcal
