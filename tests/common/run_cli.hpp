// Runs the scalcal binary as a user would, capturing exit status, stdout and stderr.
#pragma once
#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace scalcal::testing {

struct CliResult {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The test process's own folder for the files its runs read and write, removed when the process ends (ctest runs
// each test as a process of its own: left behind, they were thousands of folders in /tmp per run). Only the process
// that made it removes it: a forked child that exited normally must not take it from its parent.
class ScratchDir {
 public:
  ScratchDir()
      : owner_(getpid()),
        path_(std::filesystem::temp_directory_path() / ("scalcal_cli_test_" + std::to_string(owner_))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // a folder already gone, or a file still open elsewhere: nothing to report
    if (getpid() == owner_) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

inline std::filesystem::path scratch_dir() {
  static const ScratchDir dir;
  return dir.path();
}

inline std::string write_file(const std::string& name, const std::string& content) {
  const auto path = scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

struct CliOptions {
  std::string cwd;          // run there (default: the test's own folder)
  std::string stdout_path;  // send stdout there instead of capturing it (e.g. /dev/full)
};

inline CliResult run_cli(const std::string& args, const CliOptions& options = {}) {
  static int counter = 0;
  const auto base = scratch_dir() / ("run" + std::to_string(counter++));
  const std::string out = options.stdout_path.empty() ? base.string() + ".out" : options.stdout_path;
  const std::string cmd = (options.cwd.empty() ? "" : "cd '" + options.cwd + "' && ") + std::string(SCALCAL_CLI) + " " +
                          args + " >" + out + " 2>" + base.string() + ".err </dev/null";
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  if (options.stdout_path.empty()) r.out = slurp(out);
  r.err = slurp(base.string() + ".err");
  return r;
}

// The same with the arguments as a list, each quoted for the shell (file names with spaces stay one argument).
inline CliResult run_cli(const std::vector<std::string>& args, const CliOptions& options = {}) {
  std::string line;
  for (const auto& a : args) line += " '" + a + "'";
  return run_cli(line, options);
}

// For its lifetime every run states one date: calibrate's file and its --json hold `created`, the moment of the run
// unless SOURCE_DATE_EPOCH fixes it, so two runs compared byte for byte would differ when a second ticks between them.
class FixedDate {
 public:
  FixedDate() {
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) saved_ = epoch, had_ = true;
    ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  }
  ~FixedDate() { had_ ? ::setenv("SOURCE_DATE_EPOCH", saved_.c_str(), 1) : ::unsetenv("SOURCE_DATE_EPOCH"); }
  FixedDate(const FixedDate&) = delete;
  FixedDate& operator=(const FixedDate&) = delete;

 private:
  std::string saved_;
  bool had_ = false;
};

}  // namespace scalcal::testing
