// `scalcal limits [--model NAME] [--region SPEC]... [--out FILE] [--json]`: the infimum of each normalised
// criterion over all measures on the sphere, derived symbolically, with the moments of an optimal
// measure; on a restricted region, an optimal measure found numerically and a lower bound certified
// by weak duality over the whole region, or the closed form where a theorem gives one (commands/design/limits.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands/core/common_options.hpp"
#include "commands/design/limits.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

using commands::shortest_text;

std::string decimal(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

// "D >= 61509375/4 = 1.53773e+07": the decimal only where it says something the exact form does not.
std::string exact_and_decimal(const commands::SphereLimit& s) {
  std::ostringstream d;
  d << s.value;
  return s.exact + (d.str() == s.exact ? "" : " = " + d.str());
}

// x rounded down (up) to `digits` significant digits: the ends of an enclosure printed outward, with their
// trailing zeros (so that both ends show the same digits).
std::string rounded(double x, int digits, bool up) {
  const int exponent = static_cast<int>(std::floor(std::log10(x)));
  const double unit = std::pow(10.0, exponent - (digits - 1));
  const double r = (up ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
  const int decimals = digits - 1 - exponent;
  if (exponent < -4 || exponent >= 15 || decimals < 0)
    return decimal(("%." + std::to_string(digits - 1) + "e").c_str(), r);
  return decimal(("%." + std::to_string(decimals) + "f").c_str(), r);
}

// One line per criterion: "E = 147 (proven: proofs/cap_es_limits.md)" where a theorem gives the limit,
// "A in [lower, upper] (certified: ...)" where an interval bound and an optimal measure enclose it. The
// enclosure is printed outward to the digits its gap leaves, and the gap as the power of ten above it:
// the solver's last bits differ with the BLAS kernel, and the printed text should not.
void print_region(const commands::LimitsResult& r) {
  std::cout << "region " << r.region->text() << "\n";
  for (const auto& l : r.criteria) {
    std::cout << criterion_name(l.criterion);
    if (!l.region) {
      std::cout << ": no known limit\n";
      continue;
    }
    const RegionLimit& g = *l.region;
    const std::string value = decimal("%.10g", g.value);
    switch (status_of(g)) {
      case LimitStatus::proven:
        std::cout << " = " << value << (l.region_exact.empty() || l.region_exact == value ? "" : " = " + l.region_exact)
                  << " (proven: " << g.theorem << ")";
        break;
      case LimitStatus::certified: {
        const double gap = std::max((g.value - *g.lower_bound) / g.value, 1e-15);
        const int digits = std::clamp(static_cast<int>(std::floor(-std::log10(gap))), 4, 12);
        std::cout << " in [" << rounded(*g.lower_bound, digits, false) << ", " << rounded(g.value, digits, true)
                  << "] (certified: the lower end by interval arithmetic, the upper an optimal measure's; gap below "
                  << decimal("%.0e", std::pow(10.0, std::ceil(std::log10(gap)))) << " relative)";
        break;
      }
      case LimitStatus::numerical:
        std::cout << " = " << value << " (numerical: an optimal measure's, no proven bound)";
        break;
    }
    std::cout << "; " << decimal("%.4g", g.value / *l.sphere_value) << " x the sphere's; support "
              << distinct_support(g) << " positions\n";
  }
}

void print_sphere(const commands::LimitsResult& r) {
  const bool paper9 = model_supports(r.model, ModelCapability::criteria_native);
  for (const auto& l : r.criteria) {
    if (!l.sphere) {
      if (paper9) std::cout << criterion_name(l.criterion) << ": no known limit\n";
      continue;
    }
    const auto& s = *l.sphere;
    std::cout << criterion_name(l.criterion) << " >= " << exact_and_decimal(s);
    if (paper9 && s.x4.empty())  // no exact moments derived (a build without GiNaC): b's value, x4 from it
      std::cout << "   optimal moments: E[x^2] = 1/3, E[x^2 y^2] = " << decimal("%.10g", s.b.value_or(NAN))
                << ", E[x^4] = 1/3 - 2 E[x^2 y^2], odd moments and other mixed moments 0\n";
    else if (paper9)
      std::cout << "   optimal moments: E[x^2] = 1/3, E[x^4] = " << s.x4 << ", E[x^2 y^2] = " << s.x2y2
                << ", odd moments and other mixed moments 0\n";
    else
      std::cout << "   optimal measure: " << s.measure << "; attained: " << s.attained << "\n";
  }
  if (!paper9)
    std::cout << "(model " << model_name(r.model) << ", " << model_parameters(r.model)
              << " parameters; proofs: " << visit_model(r.model, [](auto M) { return decltype(M)::proof; }) << ")\n";
}

// A thermal model: one line per criterion with its label, then the optimal set-points.
void print_thermal(const commands::ThermalLimitsResult& t) {
  std::cout << "model " << t.model.name() << " (" << t.model.parameters() << " parameters, polynomials in tau = (T - "
            << shortest_text(t.range.middle()) << ") / " << shortest_text(t.range.half_range()) << " over "
            << t.range.text() << " degC" << (t.region ? ", positions on " + t.region->text() : std::string()) << ")\n";
  for (const auto& row : t.rows) {
    std::cout << criterion_name(row.criterion);
    if (!row.limit) {
      std::cout << ": no limit (" << row.note << ")\n";
      continue;
    }
    const ThermalLimit& l = *row.limit;
    if (row.status == "proven" && row.exact.empty())  // no closed form derived (a build without GiNaC)
      std::cout << " >= " << decimal("%.10g", l.value) << " (proven: proofs/thermal_product.md)";
    else if (row.status == "proven") {  // a factor stated after "; " (a cap's D) goes after the value
      const auto semicolon = row.exact.find("; ");
      std::cout << " >= " << row.exact.substr(0, semicolon) << " = " << decimal("%.10g", l.value)
                << " (proven: proofs/thermal_product.md)"
                << (semicolon == std::string::npos ? "" : ", where " + row.exact.substr(semicolon + 2));
    } else if (row.status == "certified") {  // printed outward as print_region prints the region's own
      const double gap = std::max((l.value - l.lower_bound) / l.value, 1e-15);
      const int digits = std::clamp(static_cast<int>(std::floor(-std::log10(gap))), 4, 12);
      std::cout << " in [" << rounded(l.lower_bound, digits, false) << ", " << rounded(l.value, digits, true)
                << "] (certified: " << l.form << ", " << row.note << "; gap below "
                << decimal("%.0e", std::pow(10.0, std::ceil(std::log10(gap))))
                << " relative; proofs/thermal_product.md)";
    } else if (!std::isfinite(l.lower_bound))
      std::cout << " = " << decimal("%.10g", l.value) << " (numerically: " << l.form << ", " << row.note << ")";
    else
      std::cout << " >= " << decimal("%.8g", l.lower_bound) << ", attained within "
                << decimal("%.1e", (l.value - l.lower_bound) / l.value) << " by " << decimal("%.10g", l.value)
                << " (numerically: " << l.form << ", the temperature factor "
                << "found numerically)";
    std::cout << "\n   set-points:";
    for (std::size_t i = 0; i < l.temperature.points.size(); ++i)
      std::cout << (i ? ", " : " ")
                << decimal("%.2f", std::round(100 * t.range.celsius(l.temperature.points[i])) / 100 + 0.0) << " degC x "
                << decimal("%.4f", l.temperature.weights[i]);
    std::cout << "\n";
  }
}

// --out: one row per criterion; a cell is empty where the limit, its exact form or a proven lower
// bound is not known (the exact form is the sphere's or a theorem's on the region; the lower bound a
// region's).
void write_table(std::ostream& out, const commands::LimitsResult& r) {
  out << "criterion,limit,exact,lower_bound\n";
  if (r.thermal)
    for (const auto& row : r.thermal->rows) {
      out << criterion_name(row.criterion) << ',';
      if (row.limit)
        out << shortest_text(row.limit->value) << ',' << (row.exact.empty() ? "" : "\"" + row.exact + "\"") << ','
            << (row.status == "proven" ? "" : shortest_text(row.limit->lower_bound));
      else
        out << ",,";
      out << '\n';
    }
  for (const auto& l : r.criteria) {
    out << criterion_name(l.criterion) << ',';
    if (r.region && l.region)
      out << shortest_text(l.region->value) << "," << (l.region_exact.empty() ? "" : "\"" + l.region_exact + "\"")
          << "," << (l.region->lower_bound ? shortest_text(*l.region->lower_bound) : "");
    else if (!r.region && l.sphere)
      out << shortest_text(l.sphere->value) << ",\"" << l.sphere->exact << "\",";
    else
      out << ",,";
    out << '\n';
  }
}

int run(const commands::Values& v) {
  const auto r = commands::limits(commands::limits_request(v), terminal_progress("limits"));
  print_warnings("limits", r.warnings);
  if (v.given("--out")) write_output_file(v.text("--out"), [&](std::ostream& out) { write_table(out, r); });
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else if (r.thermal)
    print_thermal(*r.thermal);
  else if (r.region)
    print_region(r);
  else
    print_sphere(r);
  return 0;
}

const Registration reg(commands::limits_table(), run);

}  // namespace
}  // namespace scalcal::cli
