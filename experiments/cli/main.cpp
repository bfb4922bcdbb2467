// scalcal: the one CLI of the toolkit. Builds the CLI11 parser from the registered subcommands and
// dispatches. Bad options or input: one line on stderr, exit 2; a result that cannot be written:
// exit 1; `--help`, `help` and `--version` print to stdout and exit 0.
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <vector>

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <CLI/CLI.hpp>

#include "commands/core/build_features.hpp"
#include "commands/core/tool_info.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/man_page.hpp"
#include "experiments/cli/output_file.hpp"
#include "numeric/io/blas_kernel.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/resource_error.hpp"

namespace {

using scalcal::cli::commands;

void print_overview(std::ostream& out) {
  out << "scalcal " SCALCAL_VERSION ": scalar calibration programs for vector meters\n\n"
      << "usage: scalcal COMMAND [options]   (scalcal help COMMAND, scalcal COMMAND --help: every option with "
         "its unit and default)\n\n";
  for (const auto& c : commands()) out << "  " << c.usage << "\n      " << c.summary << "\n";
  std::string lacking;
  for (const auto& c : scalcal::commands::lacking_commands()) lacking += (lacking.empty() ? "" : ", ") + c.name;
  if (!lacking.empty())
    out << "\nnot in this build (made with -DSCALCAL_WITH_GINAC=OFF, without GiNaC): " << lacking << "\n";
}

// A command this build lacks (`scalcal family` without GiNaC, or `help family`): one line, exit 2; -1 for any other.
int lacking_command(const std::vector<std::string>& args) {
  const std::string name = args[0] == "help" || args[0] == "--man" ? (args.size() > 1 ? args[1] : "") : args[0];
  for (const auto& c : scalcal::commands::lacking_commands())
    if (c.name == name) {
      std::cerr << "scalcal: " << scalcal::commands::lacking_message(c) << "\n";
      return 2;
    }
  return -1;
}

// CLI11 says "--x: ..." or "--x is required"; scalcal's messages say "option --x ...".
std::string option_message(const std::string& what) { return what.rfind("--", 0) == 0 ? "option " + what : what; }

// A file whose name starts with '-' is read as an option: the message says how to give it.
std::string dash_file_hint(const std::string& token) {
  std::error_code ec;
  if (token.size() < 2 || token[0] != '-' || !std::filesystem::exists(token, ec)) return "";
  return "; '" + scalcal::display_name(token) + "' is a file: give a name that starts with '-' after -- or as ./" +
         scalcal::display_name(token);
}

// The first argument that names an existing file but was read as an option, as dash_file_hint says.
std::string dash_file_hint(const std::vector<std::string>& args) {
  for (const auto& a : args) {
    if (a == "--") break;
    if (const std::string hint = dash_file_hint(a); !hint.empty()) return hint;
  }
  return "";
}

// Anything CLI11 left over is a mistake of the user's: an unknown option or a stray argument. The
// "--" that ends the options is not one (CLI11 keeps it among the leftovers).
void reject_leftovers(const CLI::App& sub) {
  for (const auto& t : sub.remaining()) {
    if (t == "--") continue;
    if (t.size() > 1 && t[0] == '-') throw scalcal::cli::UsageError("unknown option " + t + dash_file_hint(t));
    throw scalcal::cli::UsageError("unexpected argument '" + t + "'");
  }
}

// The commands' own messages name their command (Python shows them alone): said once here.
int fail(const std::string& command, std::string message, int status) {
  if (!command.empty() && message.rfind(command + ": ", 0) == 0) message.erase(0, command.size() + 2);
  std::cerr << "scalcal" << (command.empty() ? "" : " " + command) << ": " << message << "\n";
  return status;
}

// OpenBLAS (used by Ipopt and LAPACK) reserves 128 MB of address space per thread at its first call
// and, when refused, retries for ever: under a lower `ulimit -v` the tool would hang. Measured: 120 MB
// hangs `calibrate`, 300 MB runs it.
constexpr double kMinimumAddressSpace = 256e6;

std::string address_space_too_small() {
  rlimit r{};
  if (::getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return "";
  const double limit = static_cast<double>(r.rlim_cur);
  if (limit >= kMinimumAddressSpace) return "";
  return "the address-space limit (ulimit -v) is " + std::to_string(static_cast<long long>(limit / 1e6)) +
         " MB; scalcal needs at least " + std::to_string(static_cast<long long>(kMinimumAddressSpace / 1e6)) +
         " MB (its BLAS reserves 128 MB at first use)";
}

// `scalcal --man [COMMAND]` (not in the help: the build uses it to write the man pages) prints
// scalcal(1), or scalcal-COMMAND(1).
int print_man_page(const std::vector<std::string>& args) {
  if (args.size() == 1) {
    std::cout << scalcal::cli::man_overview(commands(), SCALCAL_VERSION);
    return 0;
  }
  for (const auto& c : commands())
    if (args.size() == 2 && c.name == args[1] && c.table) {
      std::cout << scalcal::cli::man_page(*c.table, SCALCAL_VERSION);
      return 0;
    }
  if (args.size() > 2) return fail("", "--man takes at most one command name", 2);
  return fail("", "--man: unknown command '" + args[1] + "' (try `scalcal help`)", 2);
}

// What the help, the man pages and the version print is a result too: lost on a full disk, it is an
// error (exit 1), as a command's output is.
int checked(int status) {
  try {
    scalcal::cli::check_stdout();
  } catch (const scalcal::cli::OutputError& e) {
    return fail("", e.what(), 1);
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  scalcal::pin_blas_kernel();  // the same numbers on every CPU (numeric/io/blas_kernel.hpp)
#if defined(__GLIBC__)
  // Ipopt and MUMPS allocate and free their workspace at every iteration; glibc's default returned the
  // heap's top to the system each time and took fresh zeroed pages back (1.4 million page faults and
  // 443,000 brk calls in one `reproduce`). 16 MiB of slack at the top: 0.3 million faults, system time
  // 10.9 -> 7.3 s, the same peak memory (37 MiB) and the same results.
  mallopt(M_TOP_PAD, 16 << 20);
#endif
  scalcal::commands::register_family_programs();  // every family's names, for every PROGRAM argument
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_overview(std::cerr);
    return 2;
  }
  if (args[0] == "--help" || args[0] == "-h" || (args[0] == "help" && args.size() == 1)) {
    print_overview(std::cout);
    return checked(0);
  }
  if (const int status = lacking_command(args); status >= 0) return status;
  if (args[0] == "--man") return checked(print_man_page(args));

  CLI::App app("scalar calibration programs for vector meters", "scalcal");
  app.set_help_flag();
  // The version with what a bug report needs: the commit and the build type the binary was made from.
  app.set_version_flag("--version", std::string("scalcal " SCALCAL_VERSION " (commit ") +
                                        scalcal::commands::tool_commit() + ", " SCALCAL_BUILD_TYPE " build)");
  app.require_subcommand(1, 1);
  app.get_formatter()->column_width(30);
  std::map<std::string, scalcal::cli::Runner> runners;
  std::map<std::string, CLI::App*> subs;
  for (const auto& c : commands()) {
    CLI::App* sub = app.add_subcommand(c.name, c.summary);
    sub->set_help_flag("-h,--help", "print this help and exit");
    sub->allow_extras();
    runners[c.name] = c.setup(*sub);
    subs[c.name] = sub;
  }

  if (args[0] == "help") {
    const auto it = subs.find(args[1]);
    if (args.size() > 2 || it == subs.end())
      return fail("", "help takes one command name, got '" + args[1] + "' (try `scalcal help`)", 2);
    std::cout << it->second->help("scalcal");
    return checked(0);
  }
  const std::string name = args[0];
  if (name != "--version" && !subs.count(name))
    return fail("", (name.rfind("-", 0) == 0 ? "unknown option " : "unknown command ") + name + " (try `scalcal help`)",
                2);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return checked(app.exit(e));  // --help, --version
    return fail(subs.count(name) ? name : "",
                option_message(e.what()) + dash_file_hint(args) + " (see `scalcal " +
                    (subs.count(name) ? name + " --help`)" : "help`)"),
                2);
  }
  if (const std::string why = address_space_too_small(); !why.empty()) return fail(name, why, 1);
  // A date a file would state (calibrate's "created") that does not parse stops every command before
  // any work, as the reproducible-builds convention asks of a malformed SOURCE_DATE_EPOCH.
  try {
    scalcal::commands::check_source_date_epoch();
  } catch (const scalcal::UsageError& e) {
    return fail(name, e.what(), 2);
  }
  try {
    reject_leftovers(*subs.at(name));
    const int status = runners.at(name)();
    scalcal::cli::check_stdout();
    return status;
  } catch (const scalcal::cli::UsageError& e) {
    return fail(name, e.what() + std::string(" (see `scalcal ") + name + " --help`)", 2);
  } catch (const scalcal::InputError& e) {
    return fail(name, e.what(), 2);
  } catch (const scalcal::cli::OutputError& e) {
    return fail(name, e.what(), 1);
  } catch (const scalcal::ResourceError& e) {
    return fail(name, e.what(), 1);
  } catch (const std::bad_alloc&) {
    return fail(name,
                "out of memory: the system refused memory this request needs (a memory limit, or too little "
                "free memory); try a smaller request or more memory",
                1);
  } catch (const std::exception& e) {
    return fail(name, std::string("internal error: ") + e.what(), 1);
  }
}
