// The plots library: figure.hpp (a saved gnuplot script rendered to PNG + SVG) and csv_writer.hpp
// (the data behind a figure). This file only keeps the target's source list stable.
namespace scalcal::plots { int library_anchor() { return 0; } }
