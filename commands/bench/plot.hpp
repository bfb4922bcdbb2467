// `scalcal plot` as a function: the figure of a user's program (its positions on the sphere, the
// region shaded, numbered in run order for a plan file) as a gnuplot body and the CSV files it reads.
// The CLI renders it with the reproduction's figure standards (plots/figure.hpp: print size, 8 pt
// text, Paul Tol's colours) and saves the script beside the figure; nothing here draws or writes.
//
// With --log FILE --calibration CAL.json instead of a program: the log's drawing of the reproduction's
// fig13 for any log: (a) the raw outputs against time with the calibration's static intervals shaded,
// (b) each interval's |corrected mean| - |I| (the calibration's residuals) and, before calibration,
// |mean| / g - |I| with one gain g for all axes and no offsets (g: the median |mean| over |I|).
//
// Views: one cap of at most 90 degrees is drawn as tilt (radius, linear in degrees) and azimuth (in
// the cap's frame, region.hpp's azimuth_frame) about its axis; anything else as two equal-area
// (Lambert azimuthal) disks, z >= 0 seen from +z and z < 0 seen from above through the meter, both
// with x to the right and y up: a position (x, y, z) is at (x, y) / sqrt(1 + |z|), so equal areas of
// the sphere are equal areas of the disks and the rim is the equator.
#pragma once
#include <string>
#include <vector>

#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::commands {

struct PlotRequest {
  std::string name;                  // the program's name in messages and in the figure's comment
  Program program;                   // positions, in the file's order
  std::vector<int> labels;           // the number shown at each position (1-based; a plan's step)
  bool run_order = false;            // a plan file: the steps joined in order
  std::vector<std::string> regions;  // --region, else the program file's; none: no shading
  std::string out = "plot.pdf";      // FILE.pdf|png|svg: the figure's folder and stem
  std::string log, calibration;      // --log FILE --calibration CAL.json: the log's figure instead
  Warnings warnings;
};

// A file the figure's script reads, named relative to the figure's folder. The body names it only by
// `variable`, which the script sets to the file's name (plots/figure.hpp, ScriptFile): no name from
// outside (--out's stem) is ever part of the body's text.
struct PlotData {
  std::string variable;
  std::string file;
  std::string text;
};

struct PlotResult {
  std::string folder, stem;  // of --out; the script is STEM.gp beside STEM.pdf, .png, .svg
  std::string comment;       // what the figure shows, one line
  std::string view;          // "cap", "hemispheres" or "log"
  double width_cm = 0, height_cm = 0;
  std::string body;  // gnuplot commands
  std::vector<PlotData> data;
  Warnings warnings;
};

// PROGRAM [--region SPEC]... [--out FILE.pdf|png|svg], or --log FILE --calibration CAL.json [--out ...]
const CommandTable& plot_table();
PlotRequest plot_request(const Values& values);

// Throws InputError for a bad region, log or calibration, UsageError for an --out that is not .pdf,
// .png or .svg.
PlotResult plot(const PlotRequest& request);

// The log's figure (plot_log.cpp); `result` has its folder and stem.
void plot_log(const PlotRequest& request, PlotResult& result);

}  // namespace scalcal::commands
