// A figure's gnuplot script, and gnuplot run on it without a shell (figure.hpp).
#include "plots/figure.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace scalcal::plots {

namespace {

// The length of the valid UTF-8 sequence that starts at s[i] (2 to 4 bytes; 0 when it is not one:
// a stray continuation byte, a truncated or overlong sequence, a surrogate, beyond U+10FFFF).
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto at = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
  const unsigned b = at(0);
  const std::size_t n = b >= 0xC2 && b <= 0xDF ? 2 : b >= 0xE0 && b <= 0xEF ? 3 : b >= 0xF0 && b <= 0xF4 ? 4 : 0;
  if (n == 0) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((at(k) & 0xC0) != 0x80) return 0;
  const unsigned second = at(1);
  if ((b == 0xE0 && second < 0xA0) || (b == 0xED && second > 0x9F) || (b == 0xF0 && second < 0x90) ||
      (b == 0xF4 && second > 0x8F))
    return 0;
  return n;
}

// Bytes that mean nothing inside a double-quoted gnuplot string (and are no markup gnuplot's scanner
// looks for): written as they are.
bool plain(unsigned char c) { return std::isalnum(c) || std::strchr(" !#%&'()*+,-./:;<=>?[]^_{|}~", c); }

}  // namespace

// gnuplot reads "\ooo" (first digit 1-3) as three octal digits and "\0ooo" as a 0 and up to three
// more: each escape is written at its full length, so a digit after it is never taken into it.
std::string gp_quote(const std::string& s) {
  std::string q = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == 0) throw std::invalid_argument("a gnuplot string cannot hold a NUL byte");
    if (c < 0x80 && plain(c)) {
      q += s[i++];
    } else if (const std::size_t n = utf8_length(s, i); n > 0) {
      q.append(s, i, n);
      i += n;
    } else {
      char escape[8];
      std::snprintf(escape, sizeof escape, c < 0100 ? "\\0%03o" : "\\%03o", c);
      q += escape;
      ++i;
    }
  }
  return q + "\"";
}

std::string gp_file(const std::string& name) {
  if (name.find('/') != std::string::npos)
    throw std::invalid_argument("a figure's file is named without a folder, got '" + one_line(name) + "'");
  return gp_quote("./" + name);
}

std::string one_line(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (!out.empty() && out.back() == '\\') out += ' ';
  return out;
}

std::string sub(const std::string& s) { return "_{/*1.1 " + s + "}"; }
std::string sup(const std::string& s) { return "^{/*1.1 " + s + "}"; }

namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs `gnuplot SCRIPT` in `dir` with its stderr in `log`, with no shell and no folder name in any
// script text: the folder is the child's working directory, the script a name without a path.
void run_gnuplot(const std::filesystem::path& dir, const std::string& script, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string program = SCALCAL_GNUPLOT, arg = script;
  char* argv[] = {program.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int err = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("could not start gnuplot (" + program + "): " + std::strerror(err));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(std::string("waiting for gnuplot: ") + std::strerror(errno));
}

bool non_empty(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::exists(p, ec) && std::filesystem::file_size(p, ec) > 0;
}

}  // namespace

namespace {

// "%g" with up to 6 significant digits, as gnuplot reads numbers.
std::string num(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", x);
  return s;
}

long pixels(double cm, double per_inch) { return std::lround(cm / 2.54 * per_inch); }

std::string width_name(double cm) {
  if (cm <= kColumnWidthCm) return "one journal column";
  if (cm >= kPageWidthCm) return "two journal columns";
  return "between one and two journal columns";
}

// One output format: the terminal line and the file extension. The three terminals draw the same
// figure at the print size: pdfcairo measures in points (its lines are 0.5 pt per lw), pngcairo and
// svg in pixels, so their sizes, fonts and line widths are the PDF's scaled to their resolution.
// Cairo (pango) renders a font of nominal size F at F * 96/72 points: pdfcairo takes fontscale 0.75
// (its default of 0.5 would halve the text), pngcairo a nominal size of pt * ppi / 96.
struct Format {
  const char* extension;
  std::string terminal;
};

std::vector<Format> formats(const FigureSpec& spec) {
  const double png = kPngPixelsPerInch, svg = kSvgPixelsPerInch;
  return {
      {"pdf", "pdfcairo enhanced size " + num(spec.width_cm) + "cm," + num(spec.height_cm) + "cm font 'Sans," +
                  num(spec.font_pt) + "' fontscale 0.75 background rgb 'white'"},
      {"png", "pngcairo enhanced size " + std::to_string(pixels(spec.width_cm, png)) + "," +
                  std::to_string(pixels(spec.height_cm, png)) + " font 'Sans," + num(spec.font_pt * png / 96) +
                  "' linewidth " + num(0.5 * png / 72) + " pointscale " + num(png / 72)},
      {"svg", "svg enhanced size " + std::to_string(pixels(spec.width_cm, svg)) + "," +
                  std::to_string(pixels(spec.height_cm, svg)) + " font 'Sans," + num(spec.font_pt * svg / 72) +
                  "' linewidth " + num(0.5 * svg / 72) + " background rgb 'white'"},
  };
}

}  // namespace

std::string figure_script(const FigureSpec& spec) {
  std::string files;
  for (const auto& f : spec.files) {
    const bool identifier = !f.variable.empty() && !std::isdigit(static_cast<unsigned char>(f.variable[0])) &&
                            std::all_of(f.variable.begin(), f.variable.end(),
                                        [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (!identifier) throw std::invalid_argument("not a gnuplot variable: '" + one_line(f.variable) + "'");
    files += f.variable + " = " + gp_file(f.name) + "\n";
  }
  std::ostringstream script;
  const std::string name = one_line(spec.name);
  script << "# " << name << ": " << one_line(spec.comment) << "\n"
         << "# intended print width: " << num(10 * spec.width_cm) << " mm (" << width_name(spec.width_cm)
         << "), height " << num(10 * spec.height_cm) << " mm; text " << num(spec.font_pt)
         << " pt there, indices and exponents " << num(spec.font_pt * kIndexScale) << " pt\n"
         << "# " << name << ".pdf is that size; " << name << ".png the same drawing at " << num(kPngPixelsPerInch)
         << " pixels per inch, " << name << ".svg at " << num(kSvgPixelsPerInch) << " (CSS pixels)\n"
         << "# Written by `" << one_line(spec.written_by) << "`; re-make the figure with: cd <this folder> && gnuplot "
         << name << ".gp\n";
  for (const auto& f : formats(spec))
    script << "\n# ---- " << f.extension << " ----\nreset\nset terminal " << f.terminal << "\nset output "
           << gp_file(spec.name + "." + f.extension) << "\nset datafile separator ','\n"
           << files << spec.body << "\nunset output\n";
  return script.str();
}

RenderedFigure render(const std::filesystem::path& dir, const FigureSpec& spec) {
  namespace fs = std::filesystem;
  if (spec.name.empty() || spec.name.find('/') != std::string::npos || spec.name.find('\0') != std::string::npos)
    throw std::invalid_argument("a figure's name must be a file stem without a folder, got '" + one_line(spec.name) +
                                "'");
  if (!(spec.width_cm > 0 && spec.height_cm > 0))
    throw std::invalid_argument(spec.name + ": the print size must be positive");
  if (!(spec.font_pt * kIndexScale >= kMinTextPt))
    throw std::invalid_argument(spec.name + ": " + num(spec.font_pt) + " pt text has indices below " + num(kMinTextPt) +
                                " pt");
  RenderedFigure out{dir / (spec.name + ".gp"), dir / (spec.name + ".pdf"), dir / (spec.name + ".png"),
                     dir / (spec.name + ".svg")};
  {
    std::ofstream gp(out.script);
    gp << figure_script(spec);
    if (!gp) throw std::runtime_error("cannot write " + out.script.string());
  }
  for (const auto& p : {out.pdf, out.png, out.svg}) fs::remove(p);
  const fs::path log = fs::absolute(dir) / (spec.name + ".gnuplot.log");
  // gnuplot runs in the output folder so the script's relative data paths hold; its messages go to
  // a log that is kept only when it is not empty.
  run_gnuplot(fs::absolute(dir), "./" + spec.name + ".gp", log);
  const std::string messages = read_all(log);
  if (messages.empty()) fs::remove(log);
  if (!non_empty(out.pdf) || !non_empty(out.png) || !non_empty(out.svg))
    throw std::runtime_error("gnuplot did not make " + spec.name + ".pdf/.png/.svg:\n" + messages);
  return out;
}

}  // namespace scalcal::plots
