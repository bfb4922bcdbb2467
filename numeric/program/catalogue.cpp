// The named programs and the resolution of a PROGRAM argument (catalogue.hpp).
#include "numeric/program/catalogue.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/program/program_names.hpp"

namespace scalcal {

// Found beside the running executable, not at a path compiled in, so a moved or installed binary
// still finds it: <prefix>/bin/scalcal reads <prefix>/share/scalcal/data, and the build tree
// mirrors that layout (build/share/scalcal/data, copied at configure time).
std::string data_dir() {
  if (const char* env = std::getenv("SCALCAL_DATA"); env && *env) return env;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const char* up : {"..", "../.."}) {
      const std::filesystem::path candidate = exe.parent_path() / up / "share/scalcal/data";
      if (std::filesystem::exists(candidate / "table1_A.csv", ec)) return candidate.lexically_normal().string();
    }
#if defined(SCALCAL_INSTALLED_DATA) && defined(SCALCAL_BUILD_DATA)
  for (const char* compiled : {SCALCAL_INSTALLED_DATA, SCALCAL_BUILD_DATA})
    if (std::filesystem::exists(std::filesystem::path(compiled) / "table1_A.csv", ec)) return compiled;
#endif
  throw InputError("", 0,
                   "cannot find the data folder with Tables 1-3 (looked in ../share/scalcal/data beside the "
                   "executable and where scalcal was installed); set SCALCAL_DATA to the folder holding "
                   "table1_A.csv");
}

namespace {

struct TableSource {
  const char* name;
  const char* file;
  const char* description;
};

constexpr TableSource kTables[] = {
    {"table1-A", "table1_A.csv", "18 positions optimised for the A-criterion (trace K)"},
    {"table2-E", "table2_E.csv", "18 positions optimised for the E-criterion (max eigenvalue of K)"},
    {"table3-S", "table3_S.csv", "18 positions optimised for the max-diagonal criterion (Xi_B)"},
};

// Numbers inside a catalogue name: plain decimal digits (the regexes guarantee the shape), in
// range, or an InputError naming the name.
long long parse_count(const std::string& s, const std::string& name, const char* what, long long hi) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v > hi)
    throw InputError(name, 0,
                     std::string(what) + " '" + display_name(s) + "' is out of range 0.." + std::to_string(hi));
  return v;
}

double parse_phase(const std::string& s, const std::string& name) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
    throw InputError(name, 0, "phase '" + display_name(s) + "' is not a decimal number of degrees");
  if (std::abs(v) > 360) throw InputError(name, 0, "phase '" + s + "' is outside -360..360 degrees");
  return v;
}

// Names longer than this are no catalogue names (and are never given to std::regex, whose
// recursive matcher can exhaust the stack on a long input).
constexpr std::size_t kMaxNameLength = 64;

// The paper's programs and its parametric classes (Figs. 1-4, Tables 1-3) and random programs.
std::optional<Program> paper_program(const std::string& name) {
  std::smatch m;
  if (name == "classic18") return Program::classic18();
  if (name == "nine-2axes") return Program::nine_two_axes();
  if (name == "nine-3axes") return Program::nine_three_axes();
  if (name == "dodecahedral-12") return Program::dodecahedral();
  if (name == "icosahedral-20") return Program::icosahedral();
  for (const auto& t : kTables)
    if (name == t.name) return read_program_csv(data_dir() + "/" + t.file);
  if (name.size() > kMaxNameLength) return std::nullopt;
  constexpr long long max_n = kMaximumPositions;
  if (std::regex_match(name, m, std::regex(R"(rotation-(\d+)(?:-p(-?[0-9.]+))?)"))) {
    const auto k = parse_count(m[1], name, "k", max_n / 3);
    if (k < 3) throw InputError(name, 0, "a rotation program needs k >= 3 positions per ring");
    const double phase = m[2].matched ? parse_phase(m[2], name) : 0.0;
    return Program::rotation(static_cast<int>(k), phase);
  }
  if (std::regex_match(name, m, std::regex(R"(octahedral-(\d+)-(\d+)-(\d+))"))) {
    const auto a = parse_count(m[1], name, "axes multiplicity", max_n),
               e = parse_count(m[2], name, "edges multiplicity", max_n),
               d = parse_count(m[3], name, "diagonals multiplicity", max_n);
    const long long n = 6 * a + 12 * e + 8 * d;
    if (n < kMinimumPositions || n > max_n)
      throw InputError(name, 0,
                       "6*" + std::to_string(a) + " + 12*" + std::to_string(e) + " + 8*" + std::to_string(d) + " = " +
                           std::to_string(n) + " positions; a program needs " + std::to_string(kMinimumPositions) +
                           ".." + std::to_string(max_n));
    return Program::octahedral(static_cast<int>(a), static_cast<int>(e), static_cast<int>(d));
  }
  if (std::regex_match(name, m, std::regex(R"(random-(\d+)(?:-s(\d+))?)"))) {
    const auto n = parse_count(m[1], name, "N", max_n);
    if (n < 1) throw InputError(name, 0, "random program size must be 1.." + std::to_string(max_n));
    std::uint64_t seed = 1;
    if (m[2].matched) {
      const std::string t = m[2];
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), seed);
      if (ec != std::errc() || end != t.data() + t.size())
        throw InputError(name, 0, "seed '" + t + "' is out of range 0..18446744073709551615");
    }
    return Program::random(static_cast<int>(n), seed);
  }
  return std::nullopt;
}

}  // namespace

ProgramNames paper_program_names() {
  ProgramNames p;
  p.key = "paper";
  p.pattern =
      "classic18, nine-2axes, nine-3axes, rotation-K[-pDEG], octahedral-A-E-D, dodecahedral-12, icosahedral-20, "
      "table1-A, table2-E, table3-S, random-N[-sSEED]";
  p.group = "paper";
  p.resolve = paper_program;
  auto add = [&](const std::string& name, const std::string& description, const std::string& source) {
    p.listed.push_back({name, description, source});
  };
  add("classic18", "axes along/against the vector + 4 positions at 45 deg per axis pair", "Fig. 1, ref. [14]");
  add("nine-2axes", "6 axis positions + 3 projecting on two axes", "refs. [8, 14]");
  add("nine-3axes", "6 axis positions + 3 projecting on three axes", "ref. [13], Fig. 8b");
  for (int k = 3; k <= 12; ++k)
    add("rotation-" + std::to_string(k), std::to_string(k) + " positions per ring about each axis",
        k == 6 ? "Fig. 2, ref. [12]" : "Fig. 4 (stars), ref. [12]");
  add("rotation-4-p45", "4 positions per ring, phase 45 deg (the 12 edge positions)", "Fig. 4 (stars)");
  const int octa[][3] = {{0, 1, 0}, {1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 1, 1},
                         {2, 1, 0}, {1, 2, 0}, {0, 2, 1}, {2, 2, 1}, {1, 1, 2}};
  for (const auto& o : octa)
    add("octahedral-" + std::to_string(o[0]) + "-" + std::to_string(o[1]) + "-" + std::to_string(o[2]),
        "uniform projections: axes x" + std::to_string(o[0]) + ", edges x" + std::to_string(o[1]) + ", diagonals x" +
            std::to_string(o[2]),
        "Fig. 4 (squares)");
  add("dodecahedral-12", "dodecahedral jig: 12 face normals", "Fig. 4, ref. [25]");
  add("icosahedral-20", "icosahedral jig: 20 face normals", "Fig. 4, ref. [25]");
  for (const auto& t : kTables) add(t.name, t.description, std::string("Table ") + t.name[5]);
  add("random-18-s1", "18 positions uniform on the sphere, seed 1", "Fig. 4 (dashed: best of many)");
  return p;
}

std::optional<Program> named_program(const std::string& name) {
  for (const auto& entry : program_names())
    if (auto p = entry.resolve(name)) return p;
  return std::nullopt;
}

Program resolve_program(const std::string& argument) {
  if (auto p = named_program(argument)) return *p;
  std::error_code ec;  // exists() throws on a name too long for the system; with ec it says false
  if (argument == "-" || std::filesystem::exists(argument, ec) || argument.find('/') != std::string::npos ||
      argument.ends_with(".csv"))
    return read_program_csv(argument);
  throw InputError(argument, 0, "neither a catalogue name nor a file (see `scalcal catalogue`)");
}

std::vector<CatalogueEntry> catalogue() {
  std::vector<CatalogueEntry> c;
  for (const auto& entry : program_names())
    for (const auto& l : entry.listed) c.push_back({l.name, l.description, l.source, *entry.resolve(l.name)});
  return c;
}

}  // namespace scalcal
