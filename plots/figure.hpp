// A figure as a saved gnuplot script: the body (set/plot commands reading the CSV files beside
// it) is written once per output format into NAME.gp, so `cd DIR && gnuplot NAME.gp` re-makes
// NAME.pdf (pdfcairo), NAME.png (pngcairo) and NAME.svg exactly. A figure is drawn at the size a
// journal prints it, with its text in points at that size; render() writes the script and runs it
// through gnuplot (no shell: the folder is gnuplot's working directory), and throws with gnuplot's own messages when an
// output is missing.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace scalcal::plots {

// Print widths of a two-column journal page, and the smallest text allowed at print size.
inline constexpr double kColumnWidthCm = 8.5;  // one column
inline constexpr double kPageWidthCm = 17.5;   // both columns
inline constexpr double kMinTextPt = 7;
// gnuplot's enhanced text draws sub- and superscripts at 0.8 of the text around them; sub() and
// sup() ask for 1.1 of that, so 8 pt text keeps its indices at 7 pt.
inline constexpr double kIndexScale = 0.8 * 1.1;

// The raster and vector copies are the same drawing as the PDF, at these resolutions.
inline constexpr double kPngPixelsPerInch = 300;  // sharp when printed at the intended width
inline constexpr double kSvgPixelsPerInch = 96;   // CSS pixels: the SVG opens at its print size

// A data file the body reads, by a string variable the script sets: `VARIABLE = "./NAME"` (gp_file),
// so that a body names its files without holding any text from outside (`plot positions using 1:2`).
struct ScriptFile {
  std::string variable;  // a gnuplot identifier
  std::string name;      // the file in the figure's folder
};

struct FigureSpec {
  std::string name;                  // file stem: fig4 -> fig4.gp, fig4.pdf, fig4.png, fig4.svg
  std::string comment;               // one line at the top of the script: what the figure shows
  double width_cm = kColumnWidthCm;  // at print size
  double height_cm = 6.5;
  double font_pt = 8;                            // at print size; render() refuses indices below kMinTextPt
  std::string body;                              // gnuplot commands; data files are named relative to the output folder
  std::vector<ScriptFile> files;                 // set before the body, for each format
  std::string written_by = "scalcal reproduce";  // the command named in the script's header
};

struct RenderedFigure {
  std::filesystem::path script, pdf, png, svg;
};

// Throws std::invalid_argument for a size or font that cannot print as stated.
RenderedFigure render(const std::filesystem::path& dir, const FigureSpec& spec);

// The whole NAME.gp of a figure (what render() writes).
std::string figure_script(const FigureSpec& spec);

// A gnuplot string literal that holds exactly the bytes of `s` and nothing gnuplot acts on. Every
// text from outside that reaches a script goes through it. It is double-quoted, the one form that can
// hold any byte: letters, digits, plain punctuation and valid UTF-8 stay as they are, every other byte
// is an octal escape, so no quote, backslash, backtick (gnuplot substitutes commands in backquotes
// inside double quotes), '@' (a macro), '$', line break or stray byte appears as itself. Throws
// std::invalid_argument for a NUL byte, which would end the string.
std::string gp_quote(const std::string& s);

// A file in the figure's folder as gnuplot must be given it: "./NAME" through gp_quote, so that no
// name is a pipe ('<cmd' in a plot, '|cmd' as the output), standard input ('-'), a pseudo-file ('+',
// '++'), a data block ('$name') or a home folder ('~'). Throws std::invalid_argument for a name with
// a '/' (a figure's files are all in its folder).
std::string gp_file(const std::string& name);

// The text as one comment line of a script: control characters become '?', and a backslash at its
// end (which would join the next line to the comment) is followed by a space.
std::string one_line(const std::string& s);

// Enhanced-text index and exponent that stay at kMinTextPt: sub("bias") is "_{/*1.1 bias}".
std::string sub(const std::string& s);
std::string sup(const std::string& s);

// Colours, point and dash types shared by every figure, so a program class or a criterion looks the
// same everywhere.
namespace style {
// Paul Tol's "high contrast" scheme plus black: safe for red-green colour blindness, and four clearly
// different lightnesses (CIE L* 0, 29, 50, 72), so series drawn together stay apart in greyscale too.
inline constexpr const char* black = "#000000";   // L* 0
inline constexpr const char* dark = "#004488";    // blue, L* 29
inline constexpr const char* medium = "#BB5566";  // red, L* 50
inline constexpr const char* light = "#DDAA33";   // yellow, L* 72
inline constexpr const char* grey = "#777777";    // reference marks: dashed or dotted lines, open points

// Program classes (Figs. 4-7). The many uniform programs are drawn first and lightest; the jigs,
// which equal the optimum at their N, are open and drawn last so the triangle shows inside them.
inline constexpr const char* uniform = light;    // filled squares, pt 5
inline constexpr const char* rotation = medium;  // asterisks, pt 3
inline constexpr const char* optimised = dark;   // filled triangles, pt 9
inline constexpr const char* jig = black;        // open circle (pt 6) and diamond (pt 12)
inline constexpr const char* random = grey;      // dashed line
inline constexpr const char* limit = black;      // solid line, drawn under the points
inline constexpr const char* paper = medium;     // open circles: the paper's Tables 1-3 programs

// One colour and point type per criterion D, A, E, S (kCriteria order), one colour per error group.
inline constexpr const char* criterion[4] = {black, dark, medium, light};
inline constexpr int criterion_point[4] = {5, 7, 9, 13};  // square, disc, triangle, diamond
// Curves of the four criteria drawn together (Fig. 9's ellipses) also differ in dash: D solid, A dashed,
// E dash-dot, S dash-dot-dot, so D and A (black and dark blue) stay apart in greyscale.
inline constexpr int criterion_dash[4] = {1, 2, 4, 5};
inline constexpr const char* group[3] = {dark, medium, light};  // theta_bias, theta_scale, theta_nonorth

// The error groups as figures and REPORT.md write them: the CLI's JSON keys theta_bias, theta_scale,
// theta_nonorth, set as θ with an index.
inline constexpr const char* theta_bias = "θ_{/*1.1 bias}";
inline constexpr const char* theta_scale = "θ_{/*1.1 scale}";
inline constexpr const char* theta_nonorth = "θ_{/*1.1 nonorth}";
inline constexpr const char* theta_q = "θ_{/*1.1 q}";
}  // namespace style

}  // namespace scalcal::plots
