// Errors in user input (files, options): they carry the file and line so the CLI can print
// "file:line: reason" and exit 2. Bugs are assertions, not InputErrors.
#pragma once
#include <stdexcept>
#include <string>

namespace scalcal {

// A file name or argument as it may appear in a message: longer than 200 characters, it is
// shortened to its first and last 80 with "..." between, so a message stays one readable line;
// line breaks and other control characters are shown as '?'.
inline std::string display_name(const std::string& name) {
  std::string s = name.size() > 200 ? name.substr(0, 80) + "..." + name.substr(name.size() - 80) : name;
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  return s;
}

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string reason)
      : std::runtime_error(format(file, line, reason)),
        file_(std::move(file)),
        line_(line),
        reason_(std::move(reason)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 0 when the error is not tied to one line
  const std::string& reason() const { return reason_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& reason) {
    std::string s = file.empty() ? std::string("input") : display_name(file);
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ").append(reason);
    return s;
  }
  std::string file_;
  int line_;
  std::string reason_;
};

}  // namespace scalcal
