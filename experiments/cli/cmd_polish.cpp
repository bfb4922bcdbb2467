// `scalcal polish PROGRAM --criterion D|A|E|S [--digits P] [--out FILE] [--json]`: Newton's method
// in MPFR on the first-order conditions of the criterion, from any program (a catalogue name or a
// CSV file, e.g. one written by `optimize --out`); --out writes the polished program.
#include <iomanip>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/certify/second_order.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, criterion, out;
  int digits = 50;
  bool json = false;
};

int run(const Options& o) {
  const Program program = resolve_program(o.program);
  const CriterionKind c = criterion_of(o.criterion);
  // Every criterion divides by the information matrix: refuse a rank-deficient program as evaluate does.
  const Evaluation ev = evaluate(program);
  if (!ev.full_rank()) throw InputError(o.program, 0, rank_deficiency(ev));
  PolishResult p;
  try {
    p = polish(program, c, PolishOptions{o.digits, 40});
  } catch (const std::invalid_argument& e) {
    throw InputError(o.program, 0, e.what());
  }
  if (!p.converged())
    std::cerr << "scalcal polish: " << o.program << ": warning: the polish did not converge (residual " << p.residual
              << "); value_digits keeps " << p.digits << " digits\n";
  if (!o.out.empty()) write_program_file(o.out, p.program);
  const SecondOrder second = second_order(p, c);  // numeric/certify/second_order.hpp
  if (o.json) {
    print_json(Json{{"criterion", std::string(criterion_name(c))},
                    {"positions", program.size()},
                    {"value_digits", p.value_digits},
                    {"residual", p.residual},
                    {"digits", p.digits},
                    {"iterations", p.summary.iterations},
                    {"converged", p.converged()},
                    {"second_order", second.text},
                    {"second_order_reason", second.reason},
                    {"program", program_json(p.program)}});
  } else {
    std::cout << criterion_name(c) << " = " << p.value_digits << "  (" << p.digits << " digits, residual "
              << std::setprecision(3) << p.residual << ", " << p.summary.iterations << " Newton steps, N = "
              << program.size() << (p.converged() ? "" : ", not converged") << ")\n"
              << "second order: " << second.text << (second.reason.empty() ? "" : " (" + second.reason + ")") << "\n";
  }
  // Not converged: the digits printed are fewer than asked, and a script must notice.
  return p.converged() ? 0 : 1;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "PROGRAM", o->program, "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)");
  add_criterion(app, o->criterion, kRequired);
  add_integer(app, "--digits", o->digits, 1, 1000, {"significant digits of the polished value", "significant digits"});
  add_text(app, "--out", o->out, "FILE", {"write the polished program as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"polish", "polish PROGRAM --criterion D|A|E|S [--digits P] [--out FILE] [--json]",
                        "a program polished to P digits by Newton's method in MPFR on its first-order conditions",
                        43, setup});

}  // namespace
}  // namespace scalcal::cli
