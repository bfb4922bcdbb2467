// Writing the CLI's files and stdout, each checked after closing (output_file.hpp).
#include "experiments/cli/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include "numeric/program/program_csv.hpp"

namespace scalcal::cli {

namespace {
[[noreturn]] void fail(const std::string& path, const char* what) {
  const std::string reason = errno ? std::string(": ") + std::strerror(errno) : std::string();
  throw OutputError(path + ": " + what + reason);
}
}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path) {
  errno = 0;
  out_.open(path);
  if (!out_) fail(path_, "cannot create the file");
}

void OutputFile::flush() {
  errno = 0;
  out_.flush();
  if (!out_) fail(path_, "cannot write the file");
}

void OutputFile::close() {
  errno = 0;
  out_.close();
  if (!out_) fail(path_, "cannot write the file");
}

// The whole text is made before the file is opened: a result that fails while it is formatted
// leaves no empty or half-written file behind.
void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream text;
  write(text);
  OutputFile file(path);
  file.stream() << text.str();
  file.close();
}

void write_program_file(const std::string& path, const Program& program, const std::vector<ExtraColumn>& extra,
                        const ProgramNotes& notes) {
  write_output_file(path, [&](std::ostream& out) { write_program_csv(out, program, extra, notes); });
}

void check_stdout() {
  errno = 0;
  std::cout.flush();
  // printf and std::cout share C's stdout: its error flag catches what either lost.
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) fail("standard output", "cannot write");
}

}  // namespace scalcal::cli
