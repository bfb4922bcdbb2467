// Where the CLI writes results: every file is closed and then checked, and stdout is checked at the
// end, so a full disk or /dev/full is an error naming the file (exit 1), never a short result.
// A file named "-" is standard output; the command's report then goes to standard error
// (divert_report), so the file is all that standard output carries.
#pragma once
#include <fstream>
#include <functional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "numeric/program/program.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal::cli {

// A result could not be written: main prints it and exits 1.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file written while the work goes on (rows of a long sweep survive an interruption).
class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  std::ostream& stream() { return path_ == "-" ? static_cast<std::ostream&>(pending_) : out_; }
  void flush();  // flushes and checks; throws OutputError
  void close();  // closes and checks; throws OutputError

 private:
  std::string path_;
  std::ofstream out_;
  std::ostringstream pending_;  // for "-": what is not yet written to standard output
};

// From now on, what the command prints on standard output goes to standard error, and the files
// named "-" alone go to standard output. Called once, before the command runs.
void divert_report();

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write);

// The program as CSV (x,y,z,alpha1_deg,alpha2_deg, then any extra columns), after its region line
// and comments.
void write_program_file(const std::string& path, const Program& program, const std::vector<ExtraColumn>& extra = {},
                        const ProgramNotes& notes = {});

// Flushes stdout and throws OutputError when anything written to it was lost.
void check_stdout();

}  // namespace scalcal::cli
