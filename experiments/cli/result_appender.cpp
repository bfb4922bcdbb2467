// A sweep's result file, read back and appended to (result_appender.hpp).
#include "experiments/cli/result_appender.hpp"

#include <filesystem>

#include "experiments/cli/output_file.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

// A file holding at least one whole line (a run killed while writing its first line left none: it is
// started again).
bool has_whole_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  return std::getline(in, first) && !in.eof();
}

}  // namespace

ResultAppender::ResultAppender(const std::string& path, const commands::Sweep& sweep) : path_(path) {
  if (std::filesystem::exists(path) && has_whole_line(path)) {
    std::ifstream in(path, std::ios::binary);
    done_ = commands::read_result_file(in, path);
    in.close();
    if (const std::string d = commands::request_difference(sweep.request(), done_.request); !d.empty())
      throw InputError(path, 1,
                       "holds the results of another sweep (" + d + "); give another --results file, or remove it");
    if (done_.partial_line) std::filesystem::resize_file(path, done_.whole_bytes);
    out_.open(path, std::ios::binary | std::ios::app);
  } else {
    out_.open(path, std::ios::binary | std::ios::trunc);
    out_ << commands::results_header(sweep.request()) << '\n';
  }
  out_.flush();
  if (!out_) throw OutputError("cannot write " + path);
}

std::optional<SynthesisResult> ResultAppender::find(std::size_t task) const {
  const auto it = done_.results.find(task);
  if (it == done_.results.end()) return std::nullopt;
  return it->second;
}

void ResultAppender::append(const std::string& line) {
  out_ << line << '\n';
  out_.flush();
  if (!out_) throw OutputError("cannot write " + path_);
}

}  // namespace scalcal::cli
