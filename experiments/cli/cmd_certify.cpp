// `scalcal certify PROGRAM --criterion D|A|E|S [--digits P] [--json]`: runs the interval
// certificate for one program (numeric/certify): the limit attained (proven: an exact program within
// `radius`) or missed (a certified local optimum whose value lies in `enclosure`), or says why the
// claim stays numerical.
#include <iomanip>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/certify/certify.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, criterion;
  int digits = 60;
  bool json = false;
};

int run(const Options& o) {
  const Program program = resolve_program(o.program);
  const CriterionKind c = criterion_of(o.criterion);
  if (program.size() < 9) throw UsageError("certify: " + o.program + ": a program needs at least 9 positions");
  CertifyResult r;
  try {
    r = certify(program, c, CertifyOptions{o.digits});
  } catch (const NoKnownLimit& e) {
    throw UsageError(std::string("certify: --criterion ") + o.criterion + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(o.program + ": " + e.what());
  }
  const bool local = !r.enclosure_lo.empty();  // a certified local optimum, missed or holding the limit
  if (o.json) {
    Json j{{"criterion", std::string(criterion_name(c))},
           {"positions", program.size()},
           {"status", std::string(status_text(r.status))},
           {"value", r.value},
           {"limit", r.limit},
           {"method", r.method},
           {"reason", r.reason},
           {"unknowns", r.unknowns},
           {"equations", r.equations},
           {"seconds", r.seconds}};
    j["radius"] = r.radius.empty() ? Json(nullptr) : Json(r.radius);
    j["enclosure"] = local ? Json::array({r.enclosure_lo, r.enclosure_hi}) : Json(nullptr);
    if (local) j["enclosure_digits"] = r.enclosure_digits;
    print_json(j);
  } else {
    std::cout << "status     " << status_text(r.status) << "\n"
              << "criterion  " << criterion_name(c) << " = " << std::setprecision(12) << r.value << " (limit "
              << r.limit << "), N = " << program.size() << "\n";
    if (!r.radius.empty()) std::cout << "radius     " << r.radius << "\n";
    if (local)
      std::cout << "enclosure  [" << r.enclosure_lo << ", " << r.enclosure_hi << "] (" << r.enclosure_digits
                << " digits)\n";
    std::cout << "method     " << r.method << " (" << r.unknowns << " unknowns)\n"
              << "reason     " << r.reason << "\n"
              << "seconds    " << std::setprecision(3) << r.seconds << "\n";
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "PROGRAM", o->program, "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)");
  add_criterion(app, o->criterion, kRequired);
  add_integer(app, "--digits", o->digits, 30, 400, {"working precision of the interval arithmetic", "decimal digits"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"certify", "certify PROGRAM --criterion D|A|E|S [--digits P] [--json]",
                        "proves that a program attains a limit (an exact program within a radius) or is a strict "
                        "local optimum (value enclosed), by interval arithmetic",
                        44, setup});

}  // namespace
}  // namespace scalcal::cli
