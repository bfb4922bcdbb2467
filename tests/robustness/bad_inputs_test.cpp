// Issue 16: no crash, no hang, no silent nonsense. Every bad input below is generated here (no
// committed pile of files) and run through the scalcal binary as a user would, under a time and a
// memory limit, and its class is asserted:
//   error  exit 2, exactly one line on stderr naming the file or option and the reason;
//   warn   exit 0, a result on stdout and one warning line on stderr;
//   same   exit 0, the same result as a clean reference input (BOM, CRLF, CR files);
//   write  exit 1, one line naming the file that could not be written.
// Every case checks the exit status and words of its message, so each one fails if the reader
// hangs (killed at 60 s: status 137), crashes (internal error, exit 1, or a signal), accepts the
// input silently (exit 0) or gives an unhelpful message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>

#include "numeric/program/program.hpp"
#include "tests/common/bad_input.hpp"

namespace scalcal::testing {
namespace {

// --- generators -----------------------------------------------------------------------------

std::string program_text(const Program& p, const std::string& eol = "\n", bool bom = false) {
  std::ostringstream s;
  s.precision(17);
  if (bom) s << "\xEF\xBB\xBF";
  s << "# classic18, written by the robustness test" << eol << "x,y,z" << eol;
  for (const auto& e : p.positions) s << e(0) << ',' << e(1) << ',' << e(2) << eol;
  return s.str();
}

// Bench data of a slightly miscalibrated meter on classic18: three samples per position, a
// deterministic "noise" of 1e-3 |I|, |I| = 1.
// With `mislabel`, the samples of the position opposite the first carry the first one's id and
// the nominal directions are left out (with them, the reader already refuses the file).
// With `outlier` >= 0, that sample (0-based, line outlier + 2) is ten times too large.
// `nominal_scale` multiplies the nominal directions: the reader must normalise 2^990 (1e298, whose
// square overflows) and 2^-990 (whose square underflows) alike; powers of two keep the text exact.
std::string bench_text(const std::string& eol = "\n", bool bom = false, bool mislabel = false, int outlier = -1,
                       double nominal_scale = 1) {
  std::ostringstream s;
  s.precision(17);
  if (bom) s << "\xEF\xBB\xBF";
  s << (mislabel ? "position,ix,iy,iz" : "position,ix,iy,iz,x,y,z") << eol;
  const Program p = Program::classic18();
  int k = 0;
  for (int i = 0; i < p.size(); ++i) {
    const Vec3 e = p.positions[i];
    const int id = mislabel && (e + p.positions[0]).norm() < 1e-9 ? 0 : i;
    for (int j = 0; j < 3; ++j, ++k) {
      Vec3 m(1.002 * e(0) + 0.01 + 1e-3 * std::sin(1.3 * k), 0.999 * e(1) - 0.02 + 1e-3 * std::sin(2.1 * k + 1),
             1.001 * e(2) + 0.005 + 1e-3 * std::sin(0.7 * k + 2) + 0.001 * e(0));
      if (k == outlier) m *= 10.0;
      s << id + 1 << ',' << m(0) << ',' << m(1) << ',' << m(2);
      if (!mislabel) s << ',' << nominal_scale * e(0) << ',' << nominal_scale * e(1) << ',' << nominal_scale * e(2);
      s << eol;
    }
  }
  return s.str();
}

std::string file(const std::string& name, const std::string& content) { return quote(write_file(name, content)); }

std::string repeat_lines(const std::string& header, const std::string& row, std::size_t n) {
  std::string s = header;
  s.reserve(header.size() + row.size() * n);
  for (std::size_t i = 0; i < n; ++i) s += row;
  return s;
}

std::string columns(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += (i ? ",c" : "c") + std::to_string(i);
  return s + "\n";
}

const std::string kSim = "simulate --program classic18 --trials 20 --seed 3 --modulus norm ";

std::vector<Case> cases() {
  using E = Expect;
  const std::string long_name = std::string(5000, 'a');
  return {
      // Devices and files that are not CSV.
      {"DevUrandom",
       [] { return std::string("evaluate /dev/urandom"); },
       E::error,
       {"/dev/urandom", "not a text file"}},
      {"DevZero", [] { return std::string("evaluate /dev/zero"); }, E::error, {"/dev/zero", "not a text file"}},
      {"CalibrateDevUrandom",
       [] { return std::string("calibrate --measurements /dev/urandom --magnitude 1"); },
       E::error,
       {"/dev/urandom", "not a text file"}},
      {"Directory", [] { return "evaluate " + quote(scratch_dir().string()); }, E::error, {"is a directory"}},
      {"MissingFile",
       [] { return std::string("evaluate /nonexistent/p.csv"); },
       E::error,
       {"/nonexistent/p.csv", "cannot open file"}},
      {"Utf16",
       [] { return "evaluate " + file("utf16.csv", std::string("\xFF\xFEx\0,\0y\0", 8)); },
       E::error,
       {"utf16.csv", "UTF-16"}},
      {"NulByte",
       [] { return "evaluate " + file("nul.csv", std::string("x,y,z\n1,0,\0\n", 12)); },
       E::error,
       {"nul.csv", "not a text file"}},
      {"EmptyFile", [] { return "evaluate " + file("empty.csv", ""); }, E::error, {"empty.csv", "empty file"}},
      {"FifoNoWriter",
       [] {
         const auto path = (scratch_dir() / "nowriter.fifo").string();
         ::unlink(path.c_str());
         if (::mkfifo(path.c_str(), 0600) != 0) return std::string("evaluate /cannot-make-a-fifo");
         return "evaluate " + quote(path);
       },
       E::error,
       {"nowriter.fifo", "named pipe that gave no data"}},
      // Limits.
      {"WideHeader",
       [] { return "evaluate " + file("wide.csv", columns(30000) + "1\n"); },
       E::error,
       {"wide.csv:1:", "line longer than the limit of 4096"}},
      {"ManyColumns",
       [] { return "evaluate " + file("cols.csv", columns(100)); },
       E::error,
       {"cols.csv:1:", "100 columns, more than the limit of 64"}},
      {"LongLine",
       [] { return "evaluate " + file("longline.csv", "x,y,z\n#" + std::string(5000, 'c') + "\n"); },
       E::error,
       {"longline.csv:2:", "line longer than the limit"}},
      {"HugeFile",
       [] {
         return "evaluate " + file("huge.csv", repeat_lines("x,y,z\n", "#" + std::string(1000, 'h') + "\n", 70000));
       },
       E::error,
       {"huge.csv", "larger than the limit of 64 MiB"}},
      {"TooManyPositions",
       [] { return "evaluate " + file("rows.csv", repeat_lines("x,y,z\n", "1,0,0\n", 100001)); },
       E::error,
       {"rows.csv:100002:", "limit of 100000 positions"}},
      {"TooManyRows",
       [] {
         return "calibrate --magnitude 1 --measurements " +
                file("rows.csv", repeat_lines("ix,iy,iz\n", "1,0,0\n", 1000001));
       },
       E::error,
       {"rows.csv:1000002:", "limit of 1000000 data rows"}},
      {"TooManyMeasuredPositions",
       [] {
         std::string s = "position,ix,iy,iz\n";
         for (int i = 0; i <= 100000; ++i) s += std::to_string(i) + ",1,0,0\n";
         return "calibrate --magnitude 1 --measurements " + file("mpos.csv", s);
       },
       E::error,
       {"mpos.csv:100002:", "limit of 100000 positions"}},
      {"LongFileName",
       [long_name] { return "evaluate " + quote(scratch_dir().string() + "/" + long_name + ".csv"); },
       E::error,
       {"aaaa...aaaa", "File name too long"}},
      {"LongArgument",
       [long_name] { return "evaluate " + long_name; },
       E::error,
       {"aaaa...aaaa", "neither a catalogue name nor a file"}},
      // Catalogue names.
      {"RotationHuge",
       [] { return std::string("evaluate rotation-1000000000"); },
       E::error,
       {"rotation-1000000000", "out of range 0..33333"}},
      {"RotationDigits", [] { return "evaluate rotation-" + std::string(40, '9'); }, E::error, {"out of range"}},
      {"RotationPhaseDot",
       [] { return std::string("evaluate rotation-6-p."); },
       E::error,
       {"rotation-6-p.", "phase '.' is not a decimal number"}},
      {"RotationPhaseTwoDots",
       [] { return std::string("evaluate rotation-6-p1.2.3"); },
       E::error,
       {"rotation-6-p1.2.3", "phase '1.2.3'"}},
      {"RotationPhaseLarge", [] { return std::string("evaluate rotation-6-p1000"); }, E::error, {"-360..360"}},
      {"RotationTwo", [] { return std::string("evaluate rotation-2"); }, E::error, {"rotation-2", "k >= 3"}},
      {"OctahedralEmpty",
       [] { return std::string("evaluate octahedral-0-0-0"); },
       E::error,
       {"octahedral-0-0-0", "0 positions; a program needs 3..100000"}},
      {"OctahedralHuge",
       [] { return std::string("evaluate octahedral-0-0-99999"); },
       E::error,
       {"octahedral-0-0-99999", "799992 positions"}},
      {"OctahedralOverflow",
       [] { return std::string("evaluate octahedral-99999999999999999999-0-0"); },
       E::error,
       {"axes multiplicity", "out of range"}},
      {"RandomZero", [] { return std::string("evaluate random-0"); }, E::error, {"random-0", "1..100000"}},
      {"RandomSeedHuge",
       [] { return "evaluate random-18-s" + std::string(30, '9'); },
       E::error,
       {"seed", "out of range"}},
      {"RankDeficient",
       [] { return std::string("evaluate rotation-4"); },
       E::error,
       {"rotation-4", "rank-deficient program: rank 6 of 9"}},
      // Malformed content.
      {"Overflowing",
       [] { return "evaluate " + file("big.csv", "x,y,z\n1e999,0,0\n"); },
       E::error,
       {"big.csv:2:", "'1e999' in column x is not a number"}},
      {"NotFinite",
       [] { return "evaluate " + file("nan.csv", "x,y,z\nnan,0,0\n"); },
       E::error,
       {"nan.csv:2:", "not finite"}},
      {"Ragged",
       [] { return "evaluate " + file("ragged.csv", "x,y,z\n1,0\n"); },
       E::error,
       {"ragged.csv:2:", "expected 3 values, found 2"}},
      {"ZeroVector",
       [] { return "evaluate " + file("zero.csv", "x,y,z\n0,0,0\n"); },
       E::error,
       {"zero.csv:2:", "zero vector"}},
      {"NoHeader", [] { return "evaluate " + file("nohead.csv", "1,0,0\n"); }, E::error, {"nohead.csv:1:", "header"}},
      {"FewPositions",
       [] { return "evaluate " + file("few.csv", "x,y,z\n1,0,0\n0,1,0\n"); },
       E::error,
       {"few.csv", "only 2 positions"}},
      {"MeasurementsNoColumns",
       [] { return "calibrate --magnitude 1 --measurements " + file("m.csv", "a,b\n1,2\n"); },
       E::error,
       {"m.csv:1:", "missing column 'ix'"}},
      {"MeasurementsBadPosition",
       [] { return "calibrate --magnitude 1 --measurements " + file("mp.csv", "position,ix,iy,iz\n1.5,1,0,0\n"); },
       E::error,
       {"mp.csv:2:", "position must be an integer"}},
      // Malformed option values.
      {"PositionsNotInteger",
       [] { return std::string("optimize --positions 9abc --criterion D"); },
       E::error,
       {"--positions"}},
      {"CountZero", [] { return std::string("random --positions 12 --count 0"); }, E::error, {"--count"}},
      {"CountOverLimit",
       [] { return std::string("random --positions 12 --count 2000000000"); },
       E::error,
       {"--count", "1000000000"}},
      {"ThreadsNegative",
       [] { return std::string("random --positions 12 --count 10 --threads -1"); },
       E::error,
       {"--threads"}},
      {"SeedNegative", [] { return std::string("random --positions 12 --count 10 --seed -1"); }, E::error, {"--seed"}},
      {"MagnitudeZero",
       [] { return "calibrate --magnitude 0 --measurements " + file("b.csv", bench_text()); },
       E::error,
       {"--magnitude"}},
      // In any units the norm modulus starts from an ellipsoid (issue 12); the projection modulus cannot.
      {"MagnitudeWrongUnits",
       [] { return "calibrate --magnitude 9.81 --modulus projection --measurements " + file("b.csv", bench_text()); },
       E::error,
       {"b.csv", "the projection modulus needs data in the field's units"}},
      {"ModulusUnknown",
       [] { return "calibrate --magnitude 1 --modulus foo --measurements x.csv"; },
       E::error,
       {"--modulus"}},
      {"SweepPositionsGarbage",
       [] { return std::string("sweep --positions 9abc --criteria D"); },
       E::error,
       {"--positions", "A..B"}},
      {"SweepRangeGarbage",
       [] { return std::string("sweep --positions 9..10xyz --criteria D"); },
       E::error,
       {"--positions", "A..B"}},
      {"SweepCriteriaEmpty",
       [] { return std::string("sweep --positions 12 --criteria ''"); },
       E::error,
       {"--criteria", "D, A, E, S"}},
      {"TrialsOne", [] { return kSim + "--trials 1 --noise 1e-3"; }, E::error, {"--trials"}},
      {"NoiseTen", [] { return kSim + "--noise 10"; }, E::error, {"option --noise", "meaningless"}},
      {"NoiseHuge", [] { return kSim + "--noise 1e300"; }, E::error, {"option --noise", "meaningless"}},
      {"NoiseTiny", [] { return kSim + "--noise 1e-300"; }, E::error, {"option --noise", "resolution of a double"}},
      {"NoiseInf", [] { return kSim + "--noise inf"; }, E::error, {"--noise"}},
      {"SimulateRankDeficient",
       [] { return std::string("simulate --program rotation-4 --trials 20 --noise 1e-3"); },
       E::error,
       {"rotation-4", "rank-deficient"}},
      // Runs, with a warning.
      {"NoiseHalf", [] { return kSim + "--noise 0.5"; }, E::warn, {"warning: --noise 0.5 is above 0.01"}},
      {"NoiseSmall", [] { return kSim + "--noise 1e-12"; }, E::warn, {"warning: --noise 1e-12 is below 1e-09"}},
      {"NearDegenerate",
       [] {
         // rotation-4 (rank 6) with its three rings tipped by 1e-2 rad: full rank, nearly degenerate.
         Program p = Program::rotation(4);
         for (std::size_t i = 0; i < p.positions.size(); ++i)
           p.positions[i] =
               (p.positions[i] + 1e-2 * Vec3(std::sin(i + 1.0), std::cos(2.0 * i), std::sin(3.0 * i + 2))).normalized();
         return "simulate --trials 20 --seed 3 --modulus norm --noise 1e-3 --program " +
                file("degen.csv", program_text(p));
       },
       E::warn,
       {"degen.csv", "estimates spread by"}},
      // Mislabelled positions (two directions under one label) make the fit run to the edge of the
      // model: exit 1, not a warning class (tests/calibration/cli_test.cpp, issue 31).
      {"OneSampleTenTimesOff",
       [] {
         return "calibrate --magnitude 1 --measurements " + file("outlier.csv", bench_text("\n", false, false, 7));
       },
       E::warn,
       {"outlier.csv", "excluded 1 outlier sample", "line 9 ("}},
      // Spreadsheet exports read exactly as the clean file.
      {"ProgramBomCrlf",
       [] { return "evaluate --json " + file("crlf.csv", program_text(Program::classic18(), "\r\n", true)); },
       E::same,
       {},
       [] { return "evaluate --json " + file("lf.csv", program_text(Program::classic18())); }},
      {"ProgramCr",
       [] { return "evaluate --json " + file("cr.csv", program_text(Program::classic18(), "\r")); },
       E::same,
       {},
       [] { return "evaluate --json " + file("lf.csv", program_text(Program::classic18())); }},
      {"MeasurementsBomCrlf",
       [] { return "calibrate --json --magnitude 1 --measurements " + file("bcrlf.csv", bench_text("\r\n", true)); },
       E::same,
       {},
       [] { return "calibrate --json --magnitude 1 --measurements " + file("blf.csv", bench_text()); }},
      {"NominalHuge",
       [] {
         return "calibrate --json --modulus projection --magnitude 1 --measurements " +
                file("n300.csv", bench_text("\n", false, false, -1, std::ldexp(1.0, 990)));
       },
       E::same,
       {},
       [] {
         return "calibrate --json --modulus projection --magnitude 1 --measurements " + file("n1.csv", bench_text());
       }},
      {"NominalTiny",
       [] {
         return "calibrate --json --modulus projection --magnitude 1 --measurements " +
                file("nm300.csv", bench_text("\n", false, false, -1, std::ldexp(1.0, -990)));
       },
       E::same,
       {},
       [] {
         return "calibrate --json --modulus projection --magnitude 1 --measurements " + file("n1.csv", bench_text());
       }},
      {"ProgramHuge",
       [] {
         Program p = Program::classic18();
         for (auto& e : p.positions) e *= std::ldexp(1.0, 990);
         return "evaluate --json " + file("p300.csv", program_text(p));
       },
       E::same,
       {},
       [] { return "evaluate --json " + file("lf.csv", program_text(Program::classic18())); }},
      // Raw logs and the correction (issue 12).
      {"LogTimeBackwards",
       [] {
         return "calibrate --magnitude 9.81 --measurements " + file("back.txt", "0.0 1 2 3\n0.1 1 2 3\n0.05 1 2 3\n");
       },
       E::error,
       {"back.txt:3:", "does not increase"}},
      {"LogAllNan",
       [] { return "calibrate --magnitude 9.81 --measurements " + file("nan.txt", "0.0 nan 2 3\n0.1 nan 2 3\n"); },
       E::error,
       {"nan.txt", "fewer than two rows with finite t, ix, iy, iz"}},
      {"LogStillTooShort",
       [] {
         std::string text;
         for (int i = 0; i < 400; ++i)
           text += std::to_string(0.01 * i) + " " + std::to_string(32768 + i % 3) + " 32768 36000\n";
         return "calibrate --magnitude 9.81 --still 0.5 --measurements " + file("short.txt", text);
       },
       E::error,
       {"short.txt", "initial still period", "--still"}},
      {"LogOneInterval",
       [] {
         std::string text;
         for (int i = 0; i < 5000; ++i)
           text += std::to_string(0.01 * i) + " " + std::to_string(32768 + i % 3) + " " +
                   std::to_string(32700 + i % 5) + " " + std::to_string(36000 + i % 2) + "\n";
         return "calibrate --magnitude 9.81 --measurements " + file("one.txt", text);
       },
       E::error,
       {"one.txt", "found 1 static intervals", "needs at least 9"}},
      {"MagnitudeGarbage",
       [] { return std::string("calibrate --magnitude 9.81x --measurements x.txt"); },
       E::error,
       {"--magnitude", "positive number or auto"}},
      {"FormatUnknown",
       [] { return std::string("calibrate --magnitude 9.81 --format xml --measurements x.txt"); },
       E::error,
       {"--format"}},
      {"CorrectNoCalibration",
       [] { return std::string("correct --calibration /nonexistent/cal.json --measurements x.txt"); },
       E::error,
       {"/nonexistent/cal.json", "cannot open file"}},
      {"CorrectNotJson",
       [] {
         return "correct --calibration " + file("cal.json", "{\"offset\": [1, 2]") + " --measurements " +
                file("m.txt", "0 1 2 3\n");
       },
       E::error,
       {"cal.json", "not a JSON object"}},
      // Regions of a bench (issue 11): malformed, out of range, degenerate, unreadable, refused.
      {"RegionNotANumber",
       [] { return std::string("limits --region cap:abc"); },
       E::error,
       {"--region", "'abc' is not a number"}},
      {"RegionAngleRange",
       [] { return std::string("optimize --positions 12 --region cap:200"); },
       E::error,
       {"--region", "outside [0, 180] degrees"}},
      {"RegionZeroAxis",
       [] { return std::string("random --positions 12 --count 10 --region cap:30:0,0,0"); },
       E::error,
       {"--region", "zero vector"}},
      {"RegionUnknown",
       [] { return std::string("sweep --positions 12 --criteria D --region torus:3"); },
       E::error,
       {"--region", "unknown region 'torus'"}},
      {"RegionEmptyBand",
       [] { return std::string("evaluate classic18 --region band:60:60"); },
       E::error,
       {"--region", "LO must be less than HI"}},
      {"RegionGreatCircle",
       [] {
         std::string csv = "x,y,z\n";
         for (int k = 0; k < 12; ++k)
           csv += std::to_string(std::cos(0.5 * k)) + "," + std::to_string(std::sin(0.5 * k)) + ",0\n";
         return "limits --region candidates:" + file("equator.csv", csv);
       },
       E::error,
       {"--region", "rank 9", "not identifiable"}},
      {"RegionCandidatesBinary",
       [] { return std::string("limits --region candidates:/dev/urandom"); },
       E::error,
       {"/dev/urandom", "not a text file"}},
      {"RegionOutside",
       [] { return std::string("evaluate classic18 --region cap:30"); },
       E::error,
       {"classic18", "outside the region cap:30", "tilt"}},
      {"RegionDigits",
       [] { return std::string("optimize --positions 12 --region cap:60 --digits 20"); },
       E::error,
       {"--digits", "--region cap:60"}},
      {"RegionTinyCap",
       [] { return std::string("optimize --positions 12 --region cap:3 --starts 1"); },
       E::error,
       {"--region", "condition number", "beyond what double precision resolves"}},
      {"RegionSmallCap",
       // limits, not optimize: optimize adds a second, true warning (Ipopt not converging on so flat a
       // criterion) under some BLAS kernels (Haswell, Zen) and not others.
       [] { return std::string("limits --region cap:5"); },
       E::warn,
       {"warning", "condition number", "nearly confounded"}},
      // Output that cannot be written.
      {"OutFull", [] { return std::string("evaluate classic18 --out /dev/full"); }, E::write, {"/dev/full"}},
      {"OptimizeOutFull",
       [] { return std::string("optimize --positions 12 --starts 2 --out /dev/full"); },
       E::write,
       {"/dev/full"}},
      {"SweepOutFull",
       [] { return std::string("sweep --positions 12 --criteria D --starts 2 --out /dev/full"); },
       E::write,
       {"/dev/full"}},
      {"OutNoDirectory",
       [] { return std::string("evaluate classic18 --out /nonexistent/p.csv"); },
       E::write,
       {"/nonexistent/p.csv"}},
      {"CorrectOutFull",
       [] {
         return "correct --calibration " +
                file("ok.json", "{\"offset\": [0, 0, 0], \"matrix\": [[1,0,0],[0,1,0],[0,0,1]]}") + " --measurements " +
                file("m2.txt", "0 1 2 3\n0.01 1 2 3\n") + " --out /dev/full";
       },
       E::write,
       {"/dev/full"}},
      {"AugmentOutFull",
       [] { return std::string("augment --program classic18 --add 2 --region cap:60 --out /dev/full"); },
       E::write,
       {"/dev/full"}},
  };
}

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, HasItsClass) { expect_class(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Issue16, BadInput, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace scalcal::testing
