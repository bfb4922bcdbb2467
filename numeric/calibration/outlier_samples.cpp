// Single bad samples inside otherwise good positions (outlier_samples.hpp).
#include "numeric/calibration/outlier_samples.hpp"

#include <algorithm>

#include "numeric/calibration/line_list.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

double median_of(std::vector<double> v) {
  const std::size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m), v.end());
  return v[m];
}

Vec3 componentwise_median(const std::vector<Vec3>& samples) {
  Vec3 m;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> c;
    for (const auto& s : samples) c.push_back(s(k));
    m(k) = median_of(std::move(c));
  }
  return m;
}

}  // namespace

std::vector<ExcludedSample> exclude_outlier_samples(std::vector<PositionSamples>& data, double scales) {
  constexpr std::size_t kJudged = 3;
  std::vector<std::vector<double>> distance(data.size());
  std::vector<double> all, nonzero;
  for (std::size_t p = 0; p < data.size(); ++p) {
    if (data[p].samples.size() < kJudged) continue;
    const Vec3 m = componentwise_median(data[p].samples);
    for (const auto& s : data[p].samples) {
      distance[p].push_back((s - m).norm());
      all.push_back(distance[p].back());
      if (distance[p].back() > 0) nonzero.push_back(distance[p].back());
    }
  }
  if (all.empty()) return {};
  double scale = median_of(all);
  // Quantised or synthetic data can sit exactly on the median more often than not; the typical
  // non-zero distance (about one quantum) is then the scale.
  if (scale == 0) {
    if (nonzero.empty()) return {};
    scale = median_of(nonzero);
  }
  const double cut = scales * scale;

  std::vector<ExcludedSample> out;
  for (std::size_t p = 0; p < data.size(); ++p) {
    auto& d = distance[p];
    const auto beyond = static_cast<std::size_t>(std::count_if(d.begin(), d.end(), [&](double x) { return x > cut; }));
    if (beyond == 0 || 2 * beyond >= d.size()) continue;
    PositionSamples kept = data[p];
    kept.samples.clear();
    kept.sample_lines.clear();
    for (std::size_t i = 0; i < d.size(); ++i) {
      const int line = i < data[p].sample_lines.size() ? data[p].sample_lines[i] : 0;
      if (d[i] > cut) {
        out.push_back({line, static_cast<int>(p), d[i] / scale});
      } else {
        kept.samples.push_back(data[p].samples[i]);
        if (line) kept.sample_lines.push_back(line);
      }
    }
    data[p] = std::move(kept);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.distance > b.distance; });
  return out;
}

std::string outlier_warning(const std::vector<ExcludedSample>& excluded) {
  std::vector<std::pair<double, int>> worst;
  for (const auto& e : excluded) worst.emplace_back(e.distance, e.line);
  return "excluded " + std::to_string(excluded.size()) + " outlier sample" + (excluded.size() == 1 ? "" : "s") +
         " (line, distance from its position's median in robust scales):" + line_list(worst) +
         words("; {keep-outliers} keeps them");
}

}  // namespace scalcal
