// The export formats: adding one is a file with its ExportFormat and a line here.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "numeric/export/formats.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {

const std::vector<ExportFormat>& export_formats() {
  static const std::vector<ExportFormat> formats{
      json_format(), magcal_format(), imu_tk_format(), kalibr_format(), px4_format(), ardupilot_format(), c_format(),
  };
  return formats;
}

const ExportFormat* find_export_format(std::string_view name) {
  for (const auto& f : export_formats())
    if (f.name == name) return &f;
  return nullptr;
}

std::string export_format_names() {
  std::string s;
  for (const auto& f : export_formats()) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

namespace {

// Whether a text holds a number that is not one (nan, inf as printf writes them).
bool holds_nonfinite(const std::string& text) {
  for (const char* word : {"nan", "inf", "NAN", "INF"})
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
      const bool starts = at == 0 || std::strchr(" \t,[-+:", text[at - 1]) != nullptr;
      const std::size_t end = at + std::strlen(word);
      const bool ends =
          end == text.size() || std::strchr(" \t,]\n\r;", text[end]) != nullptr || text.compare(end, 5, "inity") == 0;
      if (starts && ends) return true;
    }
  return false;
}

}  // namespace

ExportOutput export_with(const ExportFormat& format, const ExportInput& in) {
  if (std::find(format.instruments.begin(), format.instruments.end(), in.instrument) == format.instruments.end())
    throw RequestError("instrument", "the " + std::string(format.name) + " export has no " +
                                         std::string(instrument_noun(in.instrument)) + " form");
  if (in.thermal && !format.thermal) {
    std::string carriers;
    for (const auto& f : export_formats())
      if (f.thermal) carriers += (carriers.empty() ? "" : " and ") + std::string(f.name);
    throw InputError(in.file, 0,
                     "it is a thermal calibration (" + in.thermal->model.name() + "), and the " +
                         std::string(format.name) + " format carries no temperature drift: " + carriers +
                         words(" carry its offsets' (export {format px4} or ardupilot)"));
  }
  if (!in.correction.matrix.allFinite() || !in.correction.offset.allFinite())
    throw InputError(in.file, 0, "its offset or matrix holds a value that is not finite");
  ExportOutput out;
  format.write(in, out);
  for (const auto& p : out.parameters)
    if (!std::isfinite(p.value)) throw InputError(in.file, 0, p.name + " would not be finite");
  if (holds_nonfinite(out.text))
    throw InputError(in.file, 0, "the " + std::string(format.name) + " text would hold a number that is not finite");
  return out;
}

}  // namespace scalcal
