// web/test/charconv_check.cpp: prints std::to_chars and std::from_chars results for many doubles, built twice by
// check.sh: with the host's g++ (libstdc++'s own floating charconv) and with em++ and web/wasm/charconv_compat.hpp;
// the two outputs must be identical, so the shim writes and reads program files as the CLI does.
#include <charconv>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace {

// A fixed generator (splitmix64), so both builds see the same numbers.
std::uint64_t next(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void write(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::printf("%.*s\n", static_cast<int>(r.ptr - buf), buf);
}

void read(const char* text) {
  double v = -1;
  const auto r = std::from_chars(text, text + std::strlen(text), v);
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  // errc by name: its numeric values differ between glibc and musl (ERANGE 34 against 68).
  const char* ec = r.ec == std::errc()                      ? "ok"
                   : r.ec == std::errc::result_out_of_range ? "out of range"
                   : r.ec == std::errc::invalid_argument    ? "invalid"
                                                            : "other";
  std::printf("read '%s': %s, used %d, bits %016" PRIx64 "\n", text, ec, static_cast<int>(r.ptr - text), bits);
}

}  // namespace

int main() {
  std::uint64_t s = 42;
  // Random bit patterns (every exponent), random values in the ranges program files hold, and edge cases.
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = next(s);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) write(v);
    write(static_cast<double>(next(s) >> 11) / 9007199254740992.0 * 2 - 1);
    const double mantissa = static_cast<double>(next(s) >> 11);  // sequenced: argument order is unspecified
    write(std::ldexp(mantissa, static_cast<int>(next(s) % 80) - 60));
  }
  for (double v : {0.0, -0.0, 1.0, -1.0, 0.1, 1e21, 1e22, 1e-7, 123456789012345680.0, 5e-324, 1.7976931348623157e308,
                   0.5773502691896258, 100.0, 1e5, 1e16, 1e17, 12345678.0})
    write(v);
  for (const char* t : {"0.1",
                        "-2.5e-3",
                        "1e400",
                        "-1e400",
                        "1e-400",
                        "+1",
                        " 1",
                        "0x10",
                        "inf",
                        "-nan",
                        "1.5abc",
                        "",
                        "-",
                        ".5",
                        "5.",
                        "1e",
                        "0.57735026918962584",
                        "5e-324",
                        "2.2250738585072011e-308",
                        "-0x1p3",
                        "infinity",
                        "1e+308",
                        "1.8e308"})
    read(t);
}
