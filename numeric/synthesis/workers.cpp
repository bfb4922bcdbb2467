// The two ways of running a batch of starts: threads (no Ipopt) and forked workers (Ipopt).
#include "numeric/synthesis/workers.hpp"

#include <csignal>
#include <exception>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include <poll.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "numeric/io/interrupt.hpp"
#include "numeric/io/resource_error.hpp"

namespace scalcal {

namespace {

// What crosses the pipe ahead of the 3N coordinates of a result.
struct RecordHeader {
  std::int32_t index;
  std::int32_t termination;
  std::int32_t iterations;
  std::int32_t padding;
  double value;
};

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

std::vector<char> encode(int index, const LocalResult& r, int positions) {
  std::vector<char> buf(sizeof(RecordHeader) + sizeof(double) * static_cast<std::size_t>(3 * positions));
  const RecordHeader h{index, static_cast<std::int32_t>(r.summary.termination), r.summary.iterations, 0, r.value};
  std::memcpy(buf.data(), &h, sizeof h);
  double* xyz = reinterpret_cast<double*>(buf.data() + sizeof h);
  for (int i = 0; i < positions; ++i)
    for (int c = 0; c < 3; ++c) xyz[3 * i + c] = r.program.positions[static_cast<std::size_t>(i)](c);
  return buf;
}

int decode(const std::vector<char>& buf, int positions, LocalResult& r) {
  RecordHeader h;
  std::memcpy(&h, buf.data(), sizeof h);
  r.value = h.value;
  r.summary.termination = static_cast<Termination>(h.termination);
  r.summary.iterations = h.iterations;
  r.program.positions.clear();
  for (int i = 0; i < positions; ++i) {
    double v[3];
    std::memcpy(v, buf.data() + sizeof h + sizeof(double) * static_cast<std::size_t>(3 * i), sizeof v);
    r.program.positions.emplace_back(v[0], v[1], v[2]);
  }
  return h.index;
}

// A worker could not be started (the process limit, memory): the ones already running are ended
// and reaped, so none outlives the call, and the reason is reported as the machine's, not a bug.
[[noreturn]] void stop_started_workers(const std::vector<pid_t>& pids, const std::vector<pollfd>& fds,
                                       const char* call) {
  const std::string reason = std::strerror(errno);
  for (const pid_t pid : pids) ::kill(pid, SIGKILL);
  for (const pid_t pid : pids) ::waitpid(pid, nullptr, 0);
  for (const pollfd& p : fds) ::close(p.fd);
  throw ResourceError(std::string("could not start worker processes: ") + call + ": " + reason);
}

// The next task's index, in memory the workers share: each takes the next task when it is free, so a
// few long tasks do not wait behind one worker's share (the results are stored by index, as before).
class SharedCounter {
 public:
  SharedCounter() {
    void* p = ::mmap(nullptr, sizeof(std::atomic<int>), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
      throw ResourceError(std::string("could not share the task counter: mmap: ") + std::strerror(errno));
    next_ = new (p) std::atomic<int>(0);
  }
  ~SharedCounter() { ::munmap(next_, sizeof(std::atomic<int>)); }
  SharedCounter(const SharedCounter&) = delete;
  SharedCounter& operator=(const SharedCounter&) = delete;
  int take() { return next_->fetch_add(1); }

 private:
  std::atomic<int>* next_;
};
static_assert(std::atomic<int>::is_always_lock_free, "the counter is shared between processes");

// Set in a worker process: it runs one batch and exits, so MUMPS state it leaves behind is never
// inherited by a later fork that matters, and its own Ipopt calls need no further child each.
bool in_worker_process = false;

}  // namespace

std::vector<LocalResult> run_in_workers(int tasks, int workers, int positions,
                                        const std::function<LocalResult(int)>& task,
                                        const std::function<void(int, int)>& progress) {
  std::vector<LocalResult> results(static_cast<std::size_t>(tasks));
  workers = std::max(1, std::min(workers, tasks));
  const std::size_t record = sizeof(RecordHeader) + sizeof(double) * static_cast<std::size_t>(3 * positions);
  std::cout.flush();  // a forked worker must not inherit (and later repeat) buffered output
  std::cerr.flush();
  std::fflush(nullptr);
  SharedCounter next;
  std::vector<pollfd> fds;
  std::vector<pid_t> pids;
  for (int w = 0; w < workers; ++w) {
    int fd[2];
    if (::pipe(fd) != 0) stop_started_workers(pids, fds, "pipe");
    const pid_t pid = ::fork();
    if (pid < 0) {
      const int error = errno;
      ::close(fd[0]);
      ::close(fd[1]);
      errno = error;
      stop_started_workers(pids, fds, "fork");
    }
    if (pid == 0) {
      in_worker_process = true;
      ::close(fd[0]);
      for (int k; (k = next.take()) < tasks;) {
        const LocalResult r = task(k);
        if (r.program.size() != positions) ::_exit(4);
        const std::vector<char> buf = encode(k, r, positions);
        write_all(fd[1], buf.data(), buf.size());
      }
      ::close(fd[1]);
      ::_exit(0);
    }
    ::close(fd[1]);
    fds.push_back({fd[0], POLLIN, 0});
    pids.push_back(pid);
  }
  std::vector<char> buf(record);
  int open = workers, done = 0;
  bool failed = false;
  std::exception_ptr stopped;  // a stop was asked (Python's Ctrl-C): end the workers, rethrow
  while (open > 0 && !stopped) {
    // A task may run for long: the stop request is looked at every 100 ms while the workers run.
    const int ready = ::poll(fds.data(), fds.size(), 100);
    if (ready < 0) {
      if (errno == EINTR) continue;
      failed = true;
      break;
    }
    if (interrupt_requested()) {
      stopped = std::make_exception_ptr(Interrupted());
      break;
    }
    for (auto& p : fds) {
      if (p.fd < 0 || !(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (!read_all(p.fd, buf.data(), record)) {
        ::close(p.fd);
        p.fd = -1;
        --open;
        continue;
      }
      LocalResult r;
      const int k = decode(buf, positions, r);
      if (k < 0 || k >= tasks) {
        failed = true;
        continue;
      }
      results[static_cast<std::size_t>(k)] = std::move(r);
      ++done;
      try {
        if (progress && tasks > 1) progress(done, tasks);
      } catch (...) {
        stopped = std::current_exception();
        break;
      }
    }
  }
  if (stopped) {
    for (const pid_t pid : pids) ::kill(pid, SIGTERM);
    for (auto& p : fds)
      if (p.fd >= 0) ::close(p.fd);
  }
  for (const pid_t pid : pids) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) failed = true;
  }
  if (stopped) std::rethrow_exception(stopped);
  if (failed || done != tasks)
    throw std::runtime_error("a worker process failed (" + std::to_string(done) + " of " + std::to_string(tasks) +
                             " tasks returned)");
  return results;
}

std::vector<LocalResult> run_in_threads(int tasks, int threads, const std::function<LocalResult(int)>& task,
                                        const std::function<void(int, int)>& progress) {
  std::vector<LocalResult> results(static_cast<std::size_t>(std::max(tasks, 0)));
  threads = std::max(1, std::min(threads, tasks));
  std::atomic<int> next{0};
  std::mutex lock;  // guards done, failure and the progress callback
  int done = 0;
  std::exception_ptr failure;
  auto work = [&] {
    for (int k; (k = next.fetch_add(1)) < tasks;) {
      try {
        check_interrupt();
        results[static_cast<std::size_t>(k)] = task(k);
        const std::lock_guard<std::mutex> g(lock);
        ++done;
        // A progress callback may throw (Python's Ctrl-C): it ends the batch like a failed task.
        if (progress && tasks > 1 && !failure) progress(done, tasks);
      } catch (...) {
        const std::lock_guard<std::mutex> g(lock);
        if (!failure) failure = std::current_exception();
        next.store(tasks);  // no new tasks
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  // A thread the system refuses (its thread limit) leaves the work to fewer threads: the results are
  // the same, since each task is computed alone and stored by its index.
  for (int t = 1; t < threads; ++t) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;
    }
  }
  work();
  for (auto& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

std::vector<std::vector<double>> run_values_in_workers(int tasks, int workers, int size,
                                                       const std::function<std::vector<double>(int)>& task,
                                                       const std::function<void(int, int)>& progress) {
  // The doubles cross the pipe as the coordinates of a program's positions.
  const int positions = (size + 2) / 3;
  const std::vector<LocalResult> records = run_in_workers(
      tasks, workers, positions,
      [&](int k) {
        std::vector<double> v = task(k);
        v.resize(static_cast<std::size_t>(3 * positions), 0.0);
        LocalResult out;
        for (int i = 0; i < positions; ++i) out.program.positions.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        return out;
      },
      progress);
  std::vector<std::vector<double>> out;
  for (const LocalResult& r : records) {
    std::vector<double> v;
    for (const Vec3& x : r.program.positions) v.insert(v.end(), {x(0), x(1), x(2)});
    v.resize(static_cast<std::size_t>(size));
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<double> run_in_child(int size, const std::function<std::vector<double>()>& f) {
  if (in_worker_process) {  // already a disposable process (region_limits' workers): no second fork
    std::vector<double> v = f();
    v.resize(static_cast<std::size_t>(size), 0.0);
    return v;
  }
  return run_values_in_workers(1, 1, size, [&](int) { return f(); })[0];
}

}  // namespace scalcal
