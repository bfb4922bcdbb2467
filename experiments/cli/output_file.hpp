// Where the CLI writes results: every file is closed and then checked, and stdout is checked at the
// end, so a full disk or /dev/full is an error naming the file (exit 1), never a short result.
#pragma once
#include <fstream>
#include <functional>
#include <ostream>
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
  std::ostream& stream() { return out_; }
  void flush();  // flushes and checks; throws OutputError
  void close();  // closes and checks; throws OutputError

 private:
  std::string path_;
  std::ofstream out_;
};

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write);

// The program as CSV (x,y,z,alpha1_deg,alpha2_deg, then any extra columns), after its region line
// and comments.
void write_program_file(const std::string& path, const Program& program, const std::vector<ExtraColumn>& extra = {},
                        const ProgramNotes& notes = {});

// Flushes stdout and throws OutputError when anything written to it was lost.
void check_stdout();

}  // namespace scalcal::cli
