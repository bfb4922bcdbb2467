// A thermal log's calibration (thermal_calibrate.hpp).
#include "commands/calibration/thermal_calibrate.hpp"

#include <algorithm>
#include <cmath>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {

int temperature_column(const CsvTable& table) {
  for (const char* name : {"temp", "temperature", "t_c"})
    if (table.has(name)) return table.column(name);
  return -1;
}

ThermalCalibration calibrate_thermal(const std::string& file, const CsvTable& table, const ThermalModel& model,
                                     const std::optional<TemperatureRange>& range, double magnitude,
                                     const StaticIntervalOptions& intervals) {
  ThermalCalibration c;
  c.file = file;
  const int tc = temperature_column(table);
  if (tc < 0)
    throw InputError(file, 0,
                     "a thermal model (" + model.name() +
                         ") needs the log's temperature: a column temp, "
                         "temperature or t_c (degrees Celsius)");
  c.temperature_column = table.columns[static_cast<std::size_t>(tc)];
  const RawLog log = raw_log_from_table(table);
  const IntervalDetection detection = detect_static_intervals(log, intervals);
  // The raw log keeps the finite rows in order; their lines find the table's rows again.
  std::vector<double> celsius_of_line(table.rows.empty() ? 1 : static_cast<std::size_t>(table.rows.back().line + 1),
                                      NAN);
  for (const auto& row : table.rows)
    celsius_of_line[static_cast<std::size_t>(row.line)] = row.values[static_cast<std::size_t>(tc)];
  for (const StaticInterval& s : detection.intervals) {
    ThermalPose p;
    p.mean.setZero();
    double celsius = 0;
    for (int i = s.begin; i <= s.end; ++i) {
      if (s.in_break(i) || !log.finite(i)) continue;
      p.mean += log.samples[static_cast<std::size_t>(i)];
      celsius += celsius_of_line[static_cast<std::size_t>(log.lines[static_cast<std::size_t>(i)])];
      ++p.samples;
    }
    if (p.samples == 0 || !std::isfinite(celsius)) continue;
    p.mean /= p.samples;
    p.celsius = celsius / p.samples;
    p.start = s.start;
    p.stop = s.stop;
    c.poses.push_back(p);
  }
  if (c.poses.empty()) throw InputError(file, 0, "no still poses found in the log");
  TemperatureRange r;
  if (range) {
    r = *range;
  } else {
    const auto [lo, hi] =
        std::minmax_element(c.poses.begin(), c.poses.end(),
                            [](const ThermalPose& a, const ThermalPose& b) { return a.celsius < b.celsius; });
    r = {lo->celsius, hi->celsius};
    if (!(r.high - r.low > 0.5))
      throw InputError(file, 0,
                       "the poses' temperatures span " + std::to_string(r.high - r.low) + " degC: " + model.name() +
                           " needs " + std::to_string(model.degree + 1) + " set-points at least");
  }
  c.fit = fit_thermal(c.poses, model, r, magnitude);
  if (!c.fit.problem.empty() && !c.fit.converged && c.fit.iterations == 0) throw InputError(file, 0, c.fit.problem);
  return c;
}

Json to_json(const ThermalCalibration& c) {
  const ThermalFit& f = c.fit;
  const auto names = f.model.parameter_names();
  const int base = f.model.base_parameters();
  Json parameters = Json::object();
  for (std::size_t i = 0; i < names.size(); ++i) {
    // Coefficients of tau^j, and of (T - middle)^j per degC^j (tau = (T - middle) / half-range).
    const int j = i < static_cast<std::size_t>(base) ? 0 : 1 + static_cast<int>((i - base) / f.model.drifting().size());
    const double per = std::pow(f.range.half_range(), -j);
    const auto k = static_cast<Eigen::Index>(i);
    parameters[names[i]] =
        Json{{"value", f.coefficients(k)},
             {"standard_error", std::isfinite(f.standard_errors(k)) ? Json(f.standard_errors(k)) : Json(nullptr)},
             {"per_degc_power", j},
             {"value_per_degc", f.coefficients(k) * per},
             {"standard_error_per_degc",
              std::isfinite(f.standard_errors(k)) ? Json(f.standard_errors(k) * per) : Json(nullptr)}};
  }
  Json poses = Json::array();
  for (std::size_t i = 0; i < c.poses.size(); ++i)
    poses.push_back(Json{{"t_c", c.poses[i].celsius},
                         {"start_s", c.poses[i].start},
                         {"stop_s", c.poses[i].stop},
                         {"mean", Json{c.poses[i].mean(0), c.poses[i].mean(1), c.poses[i].mean(2)}},
                         {"samples", c.poses[i].samples},
                         {"residual", i < f.residuals.size() ? Json(f.residuals[i]) : Json(nullptr)}});
  Json j = thermal_model_json(f.model, f.range);
  j.update(Json{{"file", c.file},
                {"temperature_column", c.temperature_column},
                {"magnitude", f.magnitude},
                {"converged", f.converged},
                {"iterations", f.iterations},
                {"rms", f.rms},
                {"condition", f.condition},
                {"problem", f.problem.empty() ? Json(nullptr) : Json(f.problem)},
                {"parameters", parameters},
                {"poses", poses}});
  return j;
}

Json thermal_model_json(const ThermalModel& model, const TemperatureRange& range) {
  return Json{{"model", model.name()},
              {"temperature_c", range.text()},
              {"reference_c", range.middle()},
              {"half_range_c", range.half_range()}};
}

}  // namespace scalcal::commands
