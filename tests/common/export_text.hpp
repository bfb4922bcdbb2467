// Reading an export's text back in tests: the numbers after a key, and NAME VALUE parameter files.
#pragma once
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace scalcal::testing {

// Every number in the text after `key` up to the end of its statement, in order.
inline std::vector<double> numbers_after(const std::string& text, const std::string& key, int count) {
  const std::regex number(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)");
  std::vector<double> out;
  std::string rest = text.substr(text.find(key) + key.size());
  for (std::sregex_iterator it(rest.begin(), rest.end(), number);
       it != std::sregex_iterator() && static_cast<int>(out.size()) < count; ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

// NAME VALUE parameters: QGroundControl's tab-separated rows or ArduPilot's NAME,VALUE.
inline std::map<std::string, double> parameters(const std::string& text) {
  std::map<std::string, double> p;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::string field;
    std::istringstream fields(line);
    const char sep = line.find('\t') != std::string::npos ? '\t' : ',';
    while (std::getline(fields, field, sep)) f.push_back(field);
    if (sep == '\t')
      p[f[2]] = std::stod(f[3]);
    else
      p[f[0]] = std::stod(f[1]);
  }
  return p;
}

}  // namespace scalcal::testing
