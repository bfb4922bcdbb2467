// A figure as a saved gnuplot script: the body (set/plot commands reading the CSV files beside
// it) is written once per output format into NAME.gp, so `cd DIR && gnuplot NAME.gp` re-makes
// NAME.png (pngcairo) and NAME.svg exactly. render() writes the script and runs it through
// gnuplot-iostream; it throws with gnuplot's own messages when an output is missing.
#pragma once
#include <filesystem>
#include <string>

namespace scalcal::plots {

struct FigureSpec {
  std::string name;     // file stem: fig4 -> fig4.gp, fig4.png, fig4.svg
  std::string comment;  // one line at the top of the script: what the figure shows
  int width = 1100;     // pixels, for both PNG and SVG
  int height = 750;
  int font_size = 15;   // readable at page width once scaled to ~16 cm
  std::string body;     // gnuplot commands; data files are named relative to the output folder
};

struct RenderedFigure {
  std::filesystem::path script, png, svg;
};

RenderedFigure render(const std::filesystem::path& dir, const FigureSpec& spec);

// A gnuplot string literal in single quotes ('' escapes a quote).
std::string gp_quote(const std::string& s);

// Colours and point types shared by every figure, so a program class looks the same everywhere.
namespace style {
inline constexpr const char* uniform = "#1b9e3e";     // green squares, as in the paper's Fig. 4
inline constexpr const char* rotation = "#d95f02";    // stars
inline constexpr const char* optimised = "#1f4e9e";   // triangles
inline constexpr const char* jig = "#7b3294";         // dodecahedron / icosahedron
inline constexpr const char* random = "#555555";      // dashed
inline constexpr const char* limit = "#c51b1b";       // analytic limit
inline constexpr const char* paper = "#b8860b";       // the paper's own Tables 1-3 programs
}  // namespace style

}  // namespace scalcal::plots
