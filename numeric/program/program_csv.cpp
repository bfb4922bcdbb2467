// Programs as CSV files, read and written (program_csv.hpp).
#include "numeric/program/program_csv.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string_view>

#include <Eigen/Geometry>

#include "numeric/io/input_error.hpp"
#include "numeric/model/direction.hpp"

namespace scalcal {
namespace {

// A file with both x,y,z and alpha1_deg,alpha2_deg is read from x,y,z; angles that name another
// direction mean the file was edited in one pair only, and which one is meant cannot be known.
// 0.1 degree allows angles rounded to one decimal (at most 0.07 degree apart).
constexpr double kAngleAgreementDeg = 0.1;

// A file's angles reduced modulo 360 before they become radians (fmod is exact): 1e20 degrees is 280
// degrees, while 1e20 * pi / 180 keeps 17 digits of a number whose remainder sits in its 21st.
Vec3 from_angles(double alpha1_deg, double alpha2_deg) {
  return Program::from_angles_deg(std::fmod(alpha1_deg, 360.0), std::fmod(alpha2_deg, 360.0));
}

void check_angles_agree(const CsvTable& t, const CsvTable::Row& row, const Vec3& eta, double alpha1, double alpha2) {
  if (!std::isfinite(alpha1) || !std::isfinite(alpha2)) throw InputError(t.file, row.line, "an angle is not finite");
  const Vec3 named = from_angles(alpha1, alpha2);
  const double apart = std::atan2(eta.cross(named).norm(), eta.dot(named)) * 180.0 / M_PI;
  if (apart > kAngleAgreementDeg) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "x,y,z and alpha1_deg,alpha2_deg name directions %.3g degrees apart (more than %.1g); "
                  "remove one pair of columns or make them agree",
                  apart, kAngleAgreementDeg);
    throw InputError(t.file, row.line, text);
  }
}

}  // namespace

Program program_from_table(const CsvTable& t) {
  Program p;
  const int x = t.column("x"), y = t.column("y"), z = t.column("z");
  const int a1 = t.column("alpha1_deg"), a2 = t.column("alpha2_deg");
  const bool cartesian = x >= 0 && y >= 0 && z >= 0;
  if (!cartesian && !(a1 >= 0 && a2 >= 0))
    throw InputError(t.file, 1, "header must name columns x,y,z or alpha1_deg,alpha2_deg");
  if (t.rows.size() > static_cast<std::size_t>(kMaximumPositions))
    throw InputError(t.file, t.rows[kMaximumPositions].line,
                     "more than the limit of " + std::to_string(kMaximumPositions) + " positions");
  for (const auto& row : t.rows) {
    Vec3 eta;
    if (cartesian) {
      const Vec3 given(row.values[x], row.values[y], row.values[z]);
      const std::optional<Vec3> u = unit_direction(given);  // full precision from 1e-323 to 1e308
      if (!given.allFinite()) throw InputError(t.file, row.line, "a component of x,y,z is not finite");
      if (!u) throw InputError(t.file, row.line, "zero vector: a position needs a direction");
      eta = *u;
      if (a1 >= 0 && a2 >= 0) check_angles_agree(t, row, eta, row.values[a1], row.values[a2]);
    } else {
      if (!std::isfinite(row.values[a1]) || !std::isfinite(row.values[a2]))
        throw InputError(t.file, row.line, "an angle is not finite");
      eta = from_angles(row.values[a1], row.values[a2]);
    }
    p.positions.push_back(eta);
  }
  if (p.size() < kMinimumPositions)
    throw InputError(t.file, 0,
                     "only " + std::to_string(p.size()) + " positions; a program needs at least " +
                         std::to_string(kMinimumPositions) + " (one per parameter)");
  return p;
}

Program read_program_csv(const std::string& path) { return program_from_table(read_csv(path)); }

Eigen::Vector2d angles_deg(const Vec3& eta) {
  const double deg = 180.0 / M_PI;
  return {std::atan2(eta(1), eta(0)) * deg, std::asin(std::clamp(eta(2), -1.0, 1.0)) * deg};
}

namespace {

// The shortest decimal text that reads back to the same double (std::to_chars' guarantee).
std::string shortest(double v) {
  std::array<char, 32> buffer;
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v).ptr;
  return std::string(buffer.data(), end);
}

}  // namespace

void write_program_csv(std::ostream& out, const Program& program, const std::vector<ExtraColumn>& extra,
                       const ProgramNotes& notes) {
  if (!notes.region.empty()) out << region_line(notes.region);
  for (const auto& c : notes.comments) out << "# " << display_name(c) << '\n';  // one line each
  out << "x,y,z,alpha1_deg,alpha2_deg";
  for (const auto& c : extra) out << ',' << c.name;
  out << '\n';
  for (std::size_t i = 0; i < program.positions.size(); ++i) {
    const Vec3& eta = program.positions[i];
    auto a = angles_deg(eta);
    // At a pole alpha1 (the azimuth) is atan2 of rounding noise, and would print another angle on
    // another CPU for the same position: 0 there, which names the same direction.
    if (std::hypot(eta(0), eta(1)) < 1e-12) a(0) = 0;
    out << shortest(eta(0)) << ',' << shortest(eta(1)) << ',' << shortest(eta(2)) << ',' << shortest(a(0)) << ','
        << shortest(a(1));
    for (const auto& c : extra) out << ',' << shortest(c.values[i]);
    out << '\n';
  }
}

// The stream is checked after close(): a full disk shows only when the buffer is flushed.
bool write_program_csv(const std::string& path, const Program& program) {
  std::ofstream out(path);
  if (!out) return false;
  write_program_csv(out, program);
  out.close();
  return !out.fail();
}

namespace {

bool needs_quotes(const std::string& spec) {
  if (spec.empty() || spec.front() == ' ' || spec.back() == ' ' || spec.front() == '\t' || spec.back() == '\t')
    return true;
  return std::any_of(spec.begin(), spec.end(), [](char c) {
    return c == ';' || c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
  });
}

std::string quoted(const std::string& spec) {
  std::string q = "\"";
  for (char c : spec) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
      q += std::string("\\") + c;
    else if (c == '\n')
      q += "\\n";
    else if (c == '\r')
      q += "\\r";
    else if (c == '\t')
      q += "\\t";
    else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", u);
      q += hex;
    } else
      q += c;
  }
  return q + "\"";
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The specs of a region line's text after "region:": ';'-separated, each bare (spaces around it
// dropped) or quoted.
std::vector<std::string> region_specs(std::string_view l, int line) {
  std::vector<std::string> specs;
  const auto fail = [line](const std::string& why) { return InputError("", line, "# region: " + why); };
  std::size_t i = 0;
  while (i <= l.size()) {
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
    std::string field;
    if (i < l.size() && l[i] == '"') {
      for (++i;; ++i) {
        if (i >= l.size()) throw fail("a quoted spec does not end");
        if (l[i] == '"') break;
        if (l[i] != '\\') {
          field += l[i];
          continue;
        }
        const char e = ++i < l.size() ? l[i] : '\0';
        if (e == '"' || e == '\\')
          field += e;
        else if (e == 'n' || e == 'r' || e == 't')
          field += e == 'n' ? '\n' : e == 'r' ? '\r' : '\t';
        else if (e == 'x' && i + 2 < l.size() && hex_digit(l[i + 1]) >= 0 && hex_digit(l[i + 2]) >= 0) {
          field += static_cast<char>(16 * hex_digit(l[i + 1]) + hex_digit(l[i + 2]));
          i += 2;
        } else
          throw fail("'\\" + std::string(1, e) + "' is not an escape of a quoted spec (\\\" \\\\ \\n \\r \\t \\xHH)");
      }
      ++i;
      while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == '\r')) ++i;
      if (i < l.size() && l[i] != ';') throw fail("text after a quoted spec: expected ';'");
      specs.push_back(field);
    } else {
      const std::size_t end = std::min(l.find(';', i), l.size());
      field = std::string(l.substr(i, end - i));
      const auto e = field.find_last_not_of(" \t\r");
      if (e != std::string::npos) specs.push_back(field.substr(0, e + 1));
      i = end;
    }
    ++i;  // past the ';' (or the end)
  }
  return specs;
}

}  // namespace

std::string region_line(const std::vector<std::string>& specs) {
  std::string line = "# region: ";
  for (std::size_t k = 0; k < specs.size(); ++k)
    line += (k ? ";" : "") + (needs_quotes(specs[k]) ? quoted(specs[k]) : specs[k]);
  return line + "\n";
}

ProgramRegion program_region(const std::string& text) {
  ProgramRegion r;
  std::size_t start = 0;
  for (int line = 1; start < text.size(); ++line) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view l(text.data() + start, end - start);
    start = end + 1;
    if (line == 1 && l.starts_with("\xEF\xBB\xBF")) l.remove_prefix(3);
    while (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
    if (!l.starts_with('#')) continue;
    l.remove_prefix(1);
    while (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
    if (!l.starts_with("region:")) continue;
    l.remove_prefix(7);
    r.specs = region_specs(l, line);
    r.line = line;
    return r;
  }
  return r;
}

ProgramRegion read_program_region(const std::string& path) {
  try {
    return program_region(read_text_file(path));
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(path, e.line(), e.reason());  // the region line's error, with the file it is in
  }
}

}  // namespace scalcal
