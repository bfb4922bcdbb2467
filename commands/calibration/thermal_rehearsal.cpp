// Thermal rehearsals' request, log and truth (thermal_rehearsal.hpp).
#include "commands/calibration/thermal_rehearsal.hpp"

#include <cmath>
#include <cstdio>

#include "commands/bench/thermal_plan.hpp"
#include "commands/calibration/thermal_calibrate.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::commands {

std::optional<ThermalRehearsalRequest> thermal_rehearsal_request(const Values& v) {
  const auto model = parse_thermal_model(v.text("--model"));
  if (!model) {
    for (const char* o : {"--temperature", "--ramp"})
      if (v.given(o))
        throw UsageError("simulate: " + option_word(o) +
                         words(" needs a thermal model, {model BASE+Tk} (e.g. paper9+T2)"));
    return std::nullopt;
  }
  if (!model_supports(model->base, ModelCapability::thermal_base))
    throw UsageError("simulate: a thermal rehearsal simulates " + calibrated_thermal_models() +
                     words(" (got {model} ") + model->name() + ")");
  if (!v.given("--log"))
    throw UsageError(words("simulate: {model} ") + model->name() + words(" writes a thermal log: give {log FILE}"));
  if (!v.given("--temperature"))
    throw UsageError(words("simulate: {model} ") + model->name() +
                     words(" needs {temperature T1..T2} (degrees Celsius)"));
  if (v.program) throw UsageError("simulate: a thermal program is a CSV file with columns x,y,z,t_c, not an array");
  for (const char* o : {"--trials", "--bench-error", "--modulus", "--samples", "--out", "--bench-file", "--meter",
                        "--tumble", "--still", "--instrument", "--format"})
    if (v.given(o)) throw UsageError(option_word(o) + " does not apply to a thermal rehearsal");
  ThermalRehearsalRequest q;
  q.model = *model;
  q.range = parse_temperature_range(v.text("--temperature"));
  q.ramp_c_per_min = v.number("--ramp");
  if (q.ramp_c_per_min > 0) {  // positions only: the ramp sets the temperatures
    if (!program_temperatures(v.text("--program")).empty())
      throw UsageError(words("simulate: {ramp} sets the temperatures, and ") + v.text("--program") +
                       words(" has a temperature column: give its positions (x,y,z) or leave out {ramp}"));
    for (const auto& e : resolve_program(v.text("--program")).positions) {
      q.program.positions.emplace_back(e);
      q.program.celsius.push_back(q.range.low);
    }
  } else {
    q.program = read_thermal_program_csv(v.text("--program"));
  }
  q.rate_hz = v.number("--rate");
  q.dwell_s = v.number("--dwell");
  q.noise = v.number("--noise");
  q.magnitude = v.number("--magnitude");
  q.size = q.drift = v.number("--size");
  q.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  if (q.noise >= 1)
    throw UsageError(words("option {noise}: must be below 1 |I| (noise as large as the measured vector)"));
  // The rehearsal's own bound (numeric/thermal/thermal_rehearsal.hpp), said in the options' words.
  if (thermal_rehearsal_samples(q) > kMaxThermalRehearsalSamples)
    throw UsageError(q.ramp_c_per_min > 0
                         ? words("{ramp}, {temperature} and {rate} ask for more than 2e7 samples: a faster "
                                 "ramp, a narrower range or a lower rate")
                         : words("{rate} x {dwell} x rows asks for more than 2e7 samples"));
  return q;
}

void write_thermal_log(std::ostream& out, const ThermalRehearsalRequest& q, const ThermalRehearsal& r) {
  out << "# thermal rehearsal: " << q.model.name() << " over " << q.range.text() << " degC, " << q.program.size()
      << (q.ramp_c_per_min > 0
              ? " positions run over and over on a ramp of " + shortest_text(q.ramp_c_per_min) + " degC/min"
              : std::string(" rows"))
      << ", noise " << shortest_text(q.noise) << " |I|, seed " << q.seed << "\n";
  out << "t,ix,iy,iz,temp\n";
  char buffer[160];
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.6f,%.9g,%.9g,%.9g,%.4f\n", r.t[i], r.samples[i](0), r.samples[i](1),
                  r.samples[i](2), r.celsius[i]);
    out << buffer;
  }
}

Json thermal_truth_json(const ThermalRehearsalRequest& q, const ThermalRehearsal& r) {
  const auto names = q.model.parameter_names();
  Json parameters = Json::object();
  for (std::size_t i = 0; i < names.size(); ++i) parameters[names[i]] = r.truth(static_cast<Eigen::Index>(i));
  Json j = thermal_model_json(q.model, q.range);
  j.update(Json{{"magnitude", q.magnitude},
                {"noise", q.noise},
                {"seed", q.seed},
                {"rows", r.t.size()},
                {"parameters", parameters}});
  return j;
}

}  // namespace scalcal::commands
