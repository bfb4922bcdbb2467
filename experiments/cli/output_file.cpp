// Writing the CLI's files and stdout, each checked after closing (output_file.hpp).
#include "experiments/cli/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "commands/core/region_request.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal::cli {

namespace {
[[noreturn]] void fail(const std::string& path, const char* what) {
  const std::string reason = errno ? std::string(": ") + std::strerror(errno) : std::string();
  throw OutputError((path == "-" ? std::string("standard output") : path) + ": " + what + reason);
}

// Where the files named "-" go: standard output, or its duplicate once the report is diverted.
int standard_output = STDOUT_FILENO;

void write_standard_output(const std::string& text) {
  errno = 0;
  std::cout.flush();  // what was printed before comes first when nothing is diverted
  std::fflush(stdout);
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(standard_output, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("-", "cannot write");
    done += static_cast<std::size_t>(n);
  }
}
}  // namespace

void divert_report() {
  std::cout.flush();
  std::fflush(stdout);
  standard_output = ::dup(STDOUT_FILENO);
  if (standard_output < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) fail("-", "cannot divert");
}

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (path_ == "-") return;
  errno = 0;
  out_.open(path);
  if (!out_) fail(path_, "cannot create the file");
}

void OutputFile::flush() {
  if (path_ == "-") {
    write_standard_output(pending_.str());
    pending_.str("");
    return;
  }
  errno = 0;
  out_.flush();
  if (!out_) fail(path_, "cannot write the file");
}

void OutputFile::close() {
  if (path_ == "-") return flush();
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
  ProgramNotes as_written = notes;  // its candidates paths as the file's folder sees them
  as_written.region = commands::specs_written_to(notes.region, path);
  write_output_file(path, [&](std::ostream& out) { write_program_csv(out, program, extra, as_written); });
}

void check_stdout() {
  errno = 0;
  std::cout.flush();
  // printf and std::cout share C's stdout: its error flag catches what either lost.
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) fail("standard output", "cannot write");
}

}  // namespace scalcal::cli
