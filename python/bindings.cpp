// The commands the Python module binds (bindings.hpp): one line each, the same functions the CLI calls.
#include "python/bindings.hpp"

#include <fstream>
#include <functional>
#include <stdexcept>
#include <type_traits>

#include "commands/bench/export.hpp"
#include "commands/bench/jig.hpp"
#include "commands/bench/plan.hpp"
#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibrate_gyro.hpp"
#include "commands/calibration/calibrate_json.hpp"
#include "commands/calibration/correct.hpp"
#include "commands/calibration/simulate.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/design/augment.hpp"
#include "commands/design/catalogue.hpp"
#include "commands/design/evaluate.hpp"
#include "commands/design/limits.hpp"
#include "commands/design/optimize.hpp"
#include "commands/design/random.hpp"
#include "commands/research/certify.hpp"
#include "commands/research/family.hpp"
#include "commands/research/polish.hpp"
#include "commands/research/sweep.hpp"
#include "commands/research/sweep_shards.hpp"
#include "numeric/io/input_error.hpp"
#ifdef SCALCAL_PYTHON_REPRODUCE
#include "experiments/reproduce/command.hpp"
#endif

namespace scalcal::python {
namespace {

using commands::Progress;
using commands::Values;

// request(values) then run(request[, progress]): a command whose function takes a progress gets one.
template <class RequestF, class RunF>
Binding bind(const commands::CommandTable& table, RequestF request, RunF run) {
  return {&table, [request, run](const Values& v, const Progress& p) {
            auto q = request(v);
            if constexpr (std::is_invocable_v<RunF, decltype(q), Progress>) {
              auto r = run(q, p);
              return Output{commands::to_json(r), r.warnings, 0};
            } else {
              auto r = run(q);
              return Output{commands::to_json(r), r.warnings, 0};
            }
          }};
}

// The polish's status is the CLI's: 1 when Newton did not converge.
Binding polish_binding() {
  return {&commands::polish_table(), [](const Values& v, const Progress& p) {
            const auto r = commands::polish(commands::polish_request(v), p);
            return Output{commands::to_json(r), r.warnings, r.polished.converged() ? 0 : 1};
          }};
}

// A sweep's rows (of one shard with shard=), in task order, as a list.
Binding sweep_binding() {
  return {&commands::sweep_table(), [](const Values& v, const Progress& p) {
            const commands::Sweep sweep(commands::sweep_request(v));
            const commands::Shard shard =
                v.given("--shard") ? *commands::read_shard(v.text("--shard")) : commands::Shard{};
            const std::vector<std::size_t> tasks = commands::shard_tasks(sweep, shard);
            commands::Json rows = commands::Json::array();
            int done = 0;
            for (const std::size_t k : tasks) {
              const commands::SweepTask& t = sweep.tasks()[k];
              rows.push_back(commands::to_json(sweep, sweep.row(t, sweep.compute(t, sweep.request().threads)), true));
              if (p) p("tasks", ++done, static_cast<int>(tasks.size()));
            }
            return Output{rows, sweep.warnings(), 0};
          }};
}

// A calibration's status is the CLI's: 1 when the fit did not converge. Python gets the calibration
// file's object (the header, units and instrument included), which saves to and loads from cal.json.
Binding calibrate_binding() {
  return {&commands::calibrate_table(), [](const Values& v, const Progress& p) {
            if (v.text("--instrument") == "gyro") {
              const auto g = commands::calibrate_gyro(commands::gyro_calibrate_request(v));
              return Output{commands::gyro_calibration_file_json(g), g.warnings, g.status()};
            }
            const auto r = commands::calibrate(commands::calibrate_request(v), p);
            return Output{commands::calibration_file_json(r), r.warnings, r.status()};
          }};
}

// A file the Python module writes for a command (a rehearsal's log and truth): never standard
// output, whose stream is the interpreter's.
void write_file(const std::string& path, const std::string& option, const std::function<void(std::ostream&)>& write) {
  if (path == "-") throw UsageError(option + ": Python writes files, not standard output ('-')");
  std::ofstream out(path, std::ios::binary);
  if (out) write(out);
  out.flush();
  if (!out) throw InputError(path, 0, "cannot be written (" + option + ")");
}

// simulate --instrument gyro --log: the gyro's log (and the accelerometer's), the truth, as the CLI writes them.
Output gyro_rehearsal(const Values& v, const commands::GyroRehearsalRequest& q) {
  const auto r = commands::rehearse_gyro(q);
  write_file(v.text("--log"), "log", [&](std::ostream& out) { commands::write_gyro_log(out, r.log.log, r.log.rate); });
  if (r.accelerometer_log)
    write_file(v.text("--accelerometer"), "accelerometer",
               [&](std::ostream& out) { commands::write_gyro_log(out, *r.accelerometer_log, {}); });
  const commands::Json truth = commands::gyro_truth_json(r);
  if (v.given("--truth"))
    write_file(v.text("--truth"), "truth", [&](std::ostream& out) { out << commands::json_text(truth, 2) << "\n"; });
  return Output{truth, r.warnings, 0};
}

// simulate --model BASE+Tk --log: the thermal log and its truth, as the CLI writes them.
Output thermal_rehearsal(const Values& v, const ThermalRehearsalRequest& q) {
  const ThermalRehearsal r = rehearse_thermal(q);
  write_file(v.text("--log"), "log", [&](std::ostream& out) { commands::write_thermal_log(out, q, r); });
  const commands::Json truth = commands::thermal_truth_json(q, r);
  if (v.given("--truth"))
    write_file(v.text("--truth"), "truth", [&](std::ostream& out) { out << commands::json_text(truth, 2) << "\n"; });
  return Output{truth, {}, 0};
}

// simulate: the Monte-Carlo's table, or a rehearsal's files (log or bench file, truth) with the
// truth returned, as the CLI's --json prints it.
Binding simulate_binding() {
  return {&commands::simulate_table(), [](const Values& v, const Progress& p) {
            const auto q = commands::simulate_request(v);
            if (q.gyro_rehearsal) return gyro_rehearsal(v, *q.gyro_rehearsal);
            if (q.thermal_rehearsal) return thermal_rehearsal(v, *q.thermal_rehearsal);
            if (!q.rehearsal) {
              const auto r = commands::simulate(q, p);
              return Output{commands::to_json(r), r.warnings, 0};
            }
            const auto r = commands::rehearse(*q.rehearsal);
            if (q.rehearsal->grouped)
              write_file(v.text("--bench-file"), "bench_file",
                         [&](std::ostream& out) { commands::write_bench_file(out, r, v.text("--bench-file")); });
            else
              write_file(v.text("--log"), "log", [&](std::ostream& out) {
                commands::write_raw_log(out, r, v.text("--format") == "text", v.text("--log"));
              });
            const commands::Json truth = commands::truth_json(r);
            if (v.given("--truth"))
              write_file(v.text("--truth"), "truth",
                         [&](std::ostream& out) { out << commands::json_text(truth, 2) << "\n"; });
            return Output{truth, r.warnings, 0};
          }};
}

}  // namespace

const std::vector<Binding>& bindings() {
  static const std::vector<Binding> all = {
      bind(
          commands::catalogue_table(), [](const Values&) { return 0; }, [](int) { return commands::catalogue(); }),
      bind(commands::evaluate_table(), commands::evaluate_request, commands::evaluate),
      calibrate_binding(),
      bind(commands::correct_table(), commands::correct_request,
           [](const commands::CorrectRequest& q) { return commands::correct(q); }),
      bind(commands::optimize_table(), commands::optimize_request, commands::optimize),
      bind(commands::random_table(), commands::random_request, commands::random_programs),
      simulate_binding(),
      sweep_binding(),
      polish_binding(),
      bind(commands::certify_table(), commands::certify_request, commands::certify),
      bind(commands::augment_table(), commands::augment_request, commands::augment),
      bind(commands::plan_table(), commands::plan_request, commands::plan),
      bind(commands::export_table(), commands::export_request, commands::export_calibration),
#ifdef SCALCAL_PYTHON_GINAC  // without GiNaC build_info() names family and jig as lacking (build_features.hpp)
      bind(commands::family_table(), commands::family_request,
           [](const commands::FamilyRequest& q) { return commands::family(q); }),
#endif
      bind(commands::limits_table(), commands::limits_request, commands::limits),
#ifdef SCALCAL_PYTHON_GINAC
      bind(commands::jig_table(), commands::jig_request, commands::jig),
#endif
#ifdef SCALCAL_PYTHON_REPRODUCE
      {&reproduce::reproduce_table(),
       [](const Values& v, const Progress&) {
         return Output{
             reproduce::to_json(reproduce::run(reproduce::reproduce_options(v), reproduce::ProgressMode::off)), {}, 0};
       }},
#endif
  };
  return all;
}

const Binding& binding(const std::string& name) {
  for (const auto& b : bindings())
    if (b.table->name == name) return b;
  throw std::out_of_range("no command " + name);
}

}  // namespace scalcal::python
