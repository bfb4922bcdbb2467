// The multistart: start k is the uniform random program of seed splitmix(seed, k), optimised by
// Riemannian Newton (D, A; Ipopt then confirms the best) or by Ipopt (E, S); starts are dealt
// round-robin to worker processes and their results stored by index, so the best program (lowest
// value, then lowest start index) never depends on scheduling.
#include "numeric/synthesis/multistart.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <iostream>
#include <chrono>
#include <limits>
#include <stdexcept>
#include <thread>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "numeric/program/program_equivalence.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal {

// E at small N has narrow basins (N = 9: about 1 start in 100 reaches the optimum), so it gets
// 256 starts up to N = 11; with exact Hessians and iteration caps a start costs 0.01-0.3 s.
int default_starts(CriterionKind criterion, int positions) {
  const int base = criterion == CriterionKind::D ? 16 : criterion == CriterionKind::E && positions <= 11 ? 256 : 32;
  return positions <= 12 ? base : base + (positions - 12);
}

int thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

namespace {

// Positions of two runs that reach the same optimum agree to about 1e-7 (Newton, Ipopt on D and
// A) or 1e-5 (Ipopt on the nonsmooth E and S); distinct optima seen so far differ by 1e-2 or more.
constexpr double kSameProgramTolerance = 1e-4;

// Ipopt's linear solver (sequential MUMPS) is not thread-safe, so starts run in forked worker
// processes; each sends back (start index, value, status, iterations, coordinates) through a pipe.
constexpr int kHeader = 4;

void write_all(int fd, const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t w = ::write(fd, p, bytes);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) ::_exit(3);
    p += w;
    bytes -= static_cast<std::size_t>(w);
  }
}

bool read_all(int fd, void* data, std::size_t bytes) {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t r = ::read(fd, p, bytes);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    bytes -= static_cast<std::size_t>(r);
  }
  return true;
}

bool uses_newton(LocalSolver solver, CriterionKind criterion) {
  return solver == LocalSolver::Automatic && newton_applies(criterion);
}

LocalResult run_local(const Program& start, CriterionKind criterion, LocalSolver solver) {
  return uses_newton(solver, criterion) ? optimize_by_newton(start, criterion) : optimize_locally(start, criterion);
}

// The E problem (an eigenvalue constraint M/N - sI = LL^T) converges poorly from a random program:
// at N = 9 random starts ended near 68.7 while the A-optimum alone has E = 12.9. So an E start first
// runs the smooth A problem and takes its result as the starting program; the A program itself is
// kept when the E stage does not improve on it.
LocalResult run_start(const SynthesisOptions& options, int k) {
  const Program start = Program::random(options.positions, start_seed(options.seed, static_cast<std::uint64_t>(k)));
  if (options.criterion != CriterionKind::E) return run_local(start, options.criterion, options.local);
  const LocalResult warm = run_local(start, CriterionKind::A, options.local);
  LocalResult out = optimize_locally(warm.program, CriterionKind::E);
  const double warm_e = criterion_value(warm.program, CriterionKind::E);
  if (!(out.value <= warm_e)) {
    out.program = warm.program;
    out.value = warm_e;
  }
  out.iterations += warm.iterations;
  return out;
}

// Runs task(k) for k < tasks in worker processes and returns the results by index.
template <class Task>
std::vector<LocalResult> run_in_workers(const SynthesisOptions& options, int starts, const Task& task) {
  std::vector<LocalResult> results(static_cast<std::size_t>(starts));
  // Even one worker is a child process: the caller's process never initialises MUMPS, whose state a
  // later fork would otherwise inherit.
  const int workers = std::max(1, std::min(thread_count(options.threads), starts));
  int done = 0;
  const std::size_t record = static_cast<std::size_t>(kHeader + 3 * options.positions);
  std::cout.flush();  // a forked worker must not inherit (and later repeat) buffered output
  std::cerr.flush();
  std::fflush(nullptr);
  std::vector<pollfd> fds;
  std::vector<pid_t> pids;
  for (int w = 0; w < workers; ++w) {
    int fd[2];
    if (::pipe(fd) != 0) throw std::runtime_error("synthesize: pipe failed");
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("synthesize: fork failed");
    if (pid == 0) {
      ::close(fd[0]);
      std::vector<double> buf(record);
      for (int k = w; k < starts; k += workers) {
        const LocalResult r = task(k);
        buf[0] = k;
        buf[1] = r.value;
        buf[2] = r.status;
        buf[3] = r.iterations + (r.converged ? 0.5 : 0.0);
        for (int i = 0; i < options.positions; ++i)
          for (int c = 0; c < 3; ++c) buf[static_cast<std::size_t>(kHeader + 3 * i + c)] = r.program.positions[static_cast<std::size_t>(i)](c);
        write_all(fd[1], buf.data(), record * sizeof(double));
      }
      ::close(fd[1]);
      ::_exit(0);
    }
    ::close(fd[1]);
    fds.push_back({fd[0], POLLIN, 0});
    pids.push_back(pid);
  }
  std::vector<double> buf(record);
  int open = workers;
  bool failed = false;
  while (open > 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      failed = true;
      break;
    }
    for (auto& p : fds) {
      if (p.fd < 0 || !(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (!read_all(p.fd, buf.data(), record * sizeof(double))) {
        ::close(p.fd);
        p.fd = -1;
        --open;
        continue;
      }
      LocalResult& r = results[static_cast<std::size_t>(buf[0])];
      r.value = buf[1];
      r.status = static_cast<int>(buf[2]);
      r.iterations = static_cast<int>(buf[3]);
      r.converged = buf[3] - r.iterations > 0.25;
      r.program.positions.clear();
      for (int i = 0; i < options.positions; ++i)
        r.program.positions.emplace_back(buf[static_cast<std::size_t>(kHeader + 3 * i)], buf[static_cast<std::size_t>(kHeader + 3 * i + 1)],
                                         buf[static_cast<std::size_t>(kHeader + 3 * i + 2)]);
      ++done;
      if (options.progress && starts > 1) options.progress(done, starts);
    }
  }
  for (const pid_t pid : pids) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) failed = true;
  }
  if (failed || done != starts)
    throw std::runtime_error("synthesize: a worker process failed (" + std::to_string(done) + " of " + std::to_string(starts) + " starts returned)");
  return results;
}

}  // namespace

SynthesisResult synthesize(const SynthesisOptions& options) {
  if (options.positions < 9) throw std::invalid_argument("synthesize: at least 9 positions are needed");
  const auto t0 = std::chrono::steady_clock::now();
  const int starts = options.starts > 0 ? options.starts : default_starts(options.criterion, options.positions);
  std::vector<LocalResult> results = run_in_workers(options, starts, [&](int k) { return run_start(options, k); });
  SynthesisResult out;
  std::size_t best = 0;
  for (std::size_t k = 1; k < results.size(); ++k)
    if (results[k].value < results[best].value) best = k;
  out.program = results[best].program;
  out.value = results[best].value;
  out.starts = starts;
  const bool newton = uses_newton(options.local, options.criterion);
  out.local_solver = newton ? "newton" : "ipopt";
  if (newton) {
    // Ipopt, from the best Newton program, must find it a KKT point of the constrained problem
    // (same value); should it find a lower one, that is kept.
    const Program best_program = out.program;
    const LocalResult check = run_in_workers(options, 1, [&](int) { return optimize_locally(best_program, options.criterion); })[0];
    out.confirmed = check.converged && check.value <= out.value * (1 + kHitTolerance);
    if (check.value < out.value) {
      out.program = check.program;
      out.value = check.value;
    }
  } else {
    out.confirmed = results[best].converged;
  }
  std::vector<Program> optima;
  for (const auto& r : results)
    if (r.value <= out.value * (1 + kHitTolerance)) optima.push_back(r.program);
  out.hits = static_cast<int>(optima.size());
  out.distinct = count_distinct(optima, symmetry_of(options.criterion), kSameProgramTolerance);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace scalcal
