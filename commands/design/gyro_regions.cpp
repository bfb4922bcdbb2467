// A rate table's region: R and its antipodes (gyro_regions.hpp).
#include "commands/design/gyro_regions.hpp"

#include <sstream>

#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/region.hpp"

namespace scalcal::commands {

Option design_instrument_option() {
  return choice_option("--instrument", {"accel", "gyro"},
                       "the meter: accel (or a magnetometer), or gyro on a single-axis rate table, whose reversed "
                       "turns add each reachable direction's antipode (Theorem 24)",
                       "accel");
}

std::vector<std::string> with_reversed_turns(const std::vector<std::string>& specs) {
  std::vector<std::string> out;
  for (const std::string& s : specs) {
    out.push_back(s);
    if (s.rfind("candidates:", 0) == 0)
      throw UsageError(
          words("{instrument gyro}: a candidates file is taken as it is; list both directions of each "
                "candidate in it (a turn reversed measures the antipode)"));
    if (s.rfind("cap:", 0) != 0 && s.rfind("band:", 0) != 0) continue;  // sphere, faces: their own antipodes
    Region one;
    add_region_spec(one, s);  // throws for a malformed spec, naming it
    const Zone& z = one.zones.at(0);
    std::ostringstream r;
    r.precision(17);
    const std::string kind = s.substr(0, s.find(':'));
    r << kind << ':';
    if (kind == "cap")
      r << z.max_tilt_deg;
    else
      r << z.min_tilt_deg << ':' << z.max_tilt_deg;
    const auto component = [](double c) { return c == 0 ? 0.0 : -c; };  // no "-0"
    r << ':' << component(z.axis(0)) << ',' << component(z.axis(1)) << ',' << component(z.axis(2));
    out.push_back(r.str());
  }
  return out;
}

std::vector<std::string> instrument_regions(const Values& v, const std::vector<std::string>& specs) {
  if (v.text("--instrument") != "gyro") return specs;
  return with_reversed_turns(specs.empty() ? std::vector<std::string>{} : specs);
}

}  // namespace scalcal::commands
