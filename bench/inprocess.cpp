// One synthesize() call timed inside this process (wall and CPU seconds, peak RSS), for the in-process
// side of bench/compare.py and for profiling: what a library or Python user waits for, without a
// process start-up. Prints one JSON object.
// usage: bench_inprocess --positions N --criterion D|A|E|S [--model NAME] [--starts K] [--seed S]
//                        [--threads T] [--local auto|newton|lbfgs|ipopt] [--repeats R]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

#include "numeric/synthesis/multistart.hpp"

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  rusage c{};
  getrusage(RUSAGE_CHILDREN, &c);  // worker processes (Ipopt starts) that have been reaped
  auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime) + s(c.ru_utime) + s(c.ru_stime);
}

}  // namespace

int main(int argc, char** argv) {
  scalcal::SynthesisOptions o;
  int repeats = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--positions")
      o.positions = std::stoi(value);
    else if (key == "--criterion")
      o.criterion = *scalcal::parse_criterion(value);
    else if (key == "--model")
      o.model = *scalcal::parse_model(value);
    else if (key == "--starts")
      o.starts = std::stoi(value);
    else if (key == "--seed")
      o.seed = std::stoull(value);
    else if (key == "--threads")
      o.threads = std::stoi(value);
    else if (key == "--repeats")
      repeats = std::stoi(value);
    else if (key == "--local")
      o.local = value == "newton"  ? scalcal::LocalSolver::Newton
                : value == "lbfgs" ? scalcal::LocalSolver::Lbfgs
                : value == "ipopt" ? scalcal::LocalSolver::Ipopt
                                   : scalcal::LocalSolver::Automatic;
    else {
      std::fprintf(stderr, "bench_inprocess: unknown option %s\n", key.c_str());
      return 2;
    }
  }
  for (int r = 0; r < repeats; ++r) {
    const double c0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    const scalcal::SynthesisResult s = scalcal::synthesize(o);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - c0;
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    std::printf(
        "{\"positions\": %d, \"criterion\": \"%s\", \"value\": %.17g, \"starts\": %d, \"hits\": %d, "
        "\"seconds\": %.6f, \"cpu_seconds\": %.6f, \"peak_mib\": %.1f, \"confirmed\": %s, \"message\": \"%s\"}\n",
        o.positions, std::string(scalcal::criterion_name(o.criterion)).c_str(), s.value, s.starts, s.hits, wall, cpu,
        static_cast<double>(u.ru_maxrss) / 1024.0, s.summary.converged() ? "true" : "false", s.summary.message.c_str());
    std::fflush(stdout);
  }
  return 0;
}
