// Man pages from the option tables (man_page.hpp). No date in the header: the same sources give the
// same bytes.
#include "experiments/cli/man_page.hpp"

#include <limits>

#include "commands/core/common_options.hpp"
#include "experiments/cli/table_options.hpp"

namespace scalcal::cli {
namespace {

using commands::Option;
using commands::OptionKind;

// Text as roff reads it literally: a backslash is \e, every '-' is \- (Debian's man renders it as the
// ASCII '-' a user copies into a shell), and a line may not start with a control character. After a
// comma a line may break (\:), as a list such as jig:{cube,octahedron,...} is wider than a terminal.
std::string roff(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else if (c == ',')
      out += ",\\:";
    else
      out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
  return out;
}

std::string upper(std::string s) {
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

// Left-adjusted (.ad l): a justified line with one long option value in it cannot be adjusted.
std::string header(const std::string& title, const std::string& version) {
  return ".TH " + upper(title) + " 1 \"\" \"scalcal " + version + "\" \"scalcal manual\"\n.ad l\n";
}

// What values the option accepts, as its check reads them (option_table.cpp): "" when only "any text".
std::string accepted(const Option& o) {
  switch (o.kind) {
    case OptionKind::integer:
      return "An integer in " + std::to_string(o.lo) + ".." + std::to_string(o.hi) + ".";
    case OptionKind::number: {
      if (o.positive) return "A positive number.";
      const double big = std::numeric_limits<double>::max();
      if (o.low == -big && o.high == big) return "A finite number.";
      return "A number in " + (o.low == -big ? std::string("-inf") : commands::shortest_text(o.low)) + ".." +
             (o.high == big ? std::string("inf") : commands::shortest_text(o.high)) + ".";
    }
    case OptionKind::choice: {
      std::string list;
      for (const auto& c : o.choices) list += (list.empty() ? "" : ", ") + c;
      return "One of: " + list + ".";
    }
    case OptionKind::repeated:
      return "May be given more than once.";
    default:
      return "";
  }
}

// One .TP entry: the option as typed, then its help line (what, unit, default) and what it accepts.
std::string option_entry(const Option& o) {
  std::string tag;
  if (o.kind == OptionKind::flag)
    tag = ".B " + roff(o.name);
  else if (!o.name.starts_with("-"))
    tag = ".I " + roff(o.name);  // a positional argument
  else
    tag = ".BI \"" + roff(o.name) + " \" \"" + roff(type_name(o)) + "\"";
  std::string body = roff(o.help());
  if (!body.empty() && body.back() != '.') body += '.';  // a sentence, as what follows is one
  const std::string more = accepted(o);
  if (!more.empty()) body += "\n" + roff(more);
  if (o.required()) body += "\nRequired.";
  return ".TP\n" + tag + "\n" + body + "\n";
}

const char* const kExitStatus =
    ".SH EXIT STATUS\n"
    "0 on success; 2 for bad options or input (one line on standard error naming the option, file or line and "
    "the reason); 1 for a result that could not be written, a computation that did not converge, or an internal "
    "error.\n";

}  // namespace

std::string man_page(const commands::CommandTable& table, const std::string& version) {
  std::string page = header("scalcal-" + table.name, version);
  page += ".SH NAME\nscalcal\\-" + roff(table.name) + " \\- " + roff(table.summary) + "\n";
  page += ".SH SYNOPSIS\n.B scalcal\n" + roff(table.usage()) + "\n";
  page += ".SH DESCRIPTION\n" + roff("scalcal " + table.name + ": " + table.summary + ".") + "\n";
  page += ".SH OPTIONS\n";
  for (const Option& o : table.options) page += option_entry(o);
  page += ".TP\n.BI \"" + roff("--request") + " \" \"FILE\"\n" + roff(request_help(table)) + ".\n";
  page += ".TP\n.BR \\-h \", \" \\-\\-help\nprint the options with their units and defaults, and exit\n";
  page += kExitStatus;
  page += ".SH SEE ALSO\n.BR scalcal (1)\n";
  return page;
}

std::string man_overview(const std::vector<Command>& commands, const std::string& version) {
  std::string page = header("scalcal", version);
  page += ".SH NAME\nscalcal \\- scalar calibration programs for vector meters\n";
  page +=
      ".SH SYNOPSIS\n.B scalcal\n.I COMMAND\n[options]\n.br\n.B scalcal help\n[\\fICOMMAND\\fR]\n.br\n"
      ".B scalcal \\-\\-version\n";
  page +=
      ".SH DESCRIPTION\nscalcal evaluates, synthesises and certifies calibration programs (sets of N "
      "measurement positions on the sphere) for the scalar calibration of vector meters, and calibrates "
      "a meter from its log.\nEach command has its own page,\n.BR scalcal\\-COMMAND (1).\n";
  page += ".SH COMMANDS\n";
  for (const auto& c : commands) page += ".TP\n.B " + roff(c.name) + "\n" + roff(c.summary) + "\n";
  page +=
      ".SH OPTIONS\n.TP\n.BR \\-h \", \" \\-\\-help\nlist the commands, and exit\n"
      ".TP\n.B \\-\\-version\nprint the version, the commit and the build type, and exit\n";
  page += kExitStatus;
  page += ".SH SEE ALSO\n";
  for (std::size_t i = 0; i < commands.size(); ++i)
    page += ".BR scalcal\\-" + roff(commands[i].name) + " (1)" + (i + 1 < commands.size() ? "," : "") + "\n";
  return page;
}

}  // namespace scalcal::cli
