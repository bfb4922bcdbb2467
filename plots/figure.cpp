#include "plots/figure.hpp"

#include <Eigen/Core>  // before gnuplot-iostream, which then enables its Eigen support
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "gnuplot-iostream.h"

namespace scalcal::plots {

std::string gp_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("''") : std::string(1, c);
  return q + "'";
}

namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A POSIX shell word in single quotes ('\'' for a quote).
std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool non_empty(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::exists(p, ec) && std::filesystem::file_size(p, ec) > 0;
}

}  // namespace

RenderedFigure render(const std::filesystem::path& dir, const FigureSpec& spec) {
  namespace fs = std::filesystem;
  RenderedFigure out{dir / (spec.name + ".gp"), dir / (spec.name + ".png"), dir / (spec.name + ".svg")};
  std::ostringstream script;
  script << "# " << spec.name << ": " << spec.comment << "\n"
         << "# Written by `scalcal reproduce`; re-make the figure with: cd <this folder> && gnuplot " << spec.name
         << ".gp\n";
  const struct {
    const char* terminal;
    const char* extension;
  } formats[] = {{"pngcairo enhanced", "png"}, {"svg enhanced", "svg"}};
  for (const auto& f : formats) {
    script << "\n# ---- " << f.extension << " ----\nreset\nset terminal " << f.terminal << " size " << spec.width
           << "," << spec.height << " font 'Sans," << spec.font_size << "'";
    if (std::string(f.extension) == "svg") script << " background rgb 'white'";
    script << "\nset output " << gp_quote(spec.name + "." + f.extension) << "\nset datafile separator ','\n"
           << spec.body << "\nunset output\n";
  }
  {
    std::ofstream gp(out.script);
    gp << script.str();
    if (!gp) throw std::runtime_error("cannot write " + out.script.string());
  }
  for (const auto& p : {out.png, out.svg}) fs::remove(p);
  const fs::path log = dir / (spec.name + ".gnuplot.log");
  {
    // gnuplot runs in the output folder so the script's relative data paths hold; its messages
    // go to a log that is kept only when it is not empty.
    Gnuplot gp(std::string(SCALCAL_GNUPLOT) + " 2> " + shell_quote(log.string()));
    gp << "cd " << gp_quote(fs::absolute(dir).string()) << "\nload " << gp_quote(spec.name + ".gp") << "\n";
  }  // the destructor waits for gnuplot to finish
  const std::string messages = read_all(log);
  if (messages.empty()) fs::remove(log);
  if (!non_empty(out.png) || !non_empty(out.svg))
    throw std::runtime_error("gnuplot did not make " + spec.name + ".png/.svg:\n" + messages);
  return out;
}

}  // namespace scalcal::plots
