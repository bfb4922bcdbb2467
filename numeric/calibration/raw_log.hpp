// A raw instrument log: time (seconds) and the three raw outputs of a triad, sample by sample, as
// a logger writes it: CSV with a header naming a time column (t, t_s, time, time_s or timestamp, in
// any case) and ix, iy, iz (other columns ignored), or whitespace-separated text without a header
// (t ix iy iz, IMU-TK's format). A log without time, or whose time column is the sample index, is
// read with a sample rate instead (--rate): CSV with ix, iy, iz, or text ix iy iz. Static positions are
// found in it later (numeric/calibration/static_intervals.hpp). NaN or infinite values (a logger's
// dropouts) are kept here and counted where the log is used, never dropped silently.
#pragma once
#include <string>
#include <vector>

#include "numeric/io/csv_table.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

enum class LogFormat {
  automatic,  // text when the first data line starts with a number, else CSV
  csv,
  text,
};

struct RawLog {
  std::string file;
  std::vector<double> t;      // seconds, strictly increasing over the finite rows
  std::vector<Vec3> samples;  // raw outputs, in the file's units
  std::vector<int> lines;     // 1-based line of each row, for messages

  int size() const { return static_cast<int>(t.size()); }
  bool finite(int i) const;  // t and all three outputs finite
};

// The time column's index (t, t_s, time, time_s, timestamp, any case), or -1.
int time_column(const CsvTable& table);
// Whether a measurements table is a raw log: a time column and no position column.
bool is_raw_log(const CsvTable& table);
// Whether a table of ix, iy, iz rows changes as a raw log does: consecutive rows close together
// (the median step under a fifth of the median distance between rows half the table apart), over
// at least 30 rows. Bench data (a position per row, or a position column) do not.
bool rows_change_like_a_log(const CsvTable& table);
// Whether a file's text is a header-less text log: its first line that is neither blank nor a
// comment starts with a number.
bool looks_like_text_log(const std::string& text);

// Throws InputError (file, line, reason): a bad file, a missing column, time that does not
// increase, fewer than two finite rows. rate > 0 (Hz): the time of row k is k / rate, whatever
// time column the file has.
RawLog read_raw_log(const std::string& path, LogFormat format = LogFormat::automatic, double rate = 0);
RawLog parse_raw_log(std::string text, const std::string& name, LogFormat format = LogFormat::automatic,
                     double rate = 0);
RawLog raw_log_from_table(const CsvTable& table, double rate = 0);

}  // namespace scalcal
