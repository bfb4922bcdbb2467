// Values of a command's options (values.hpp).
#include "commands/core/values.hpp"

#include <filesystem>
#include <stdexcept>

#include "commands/core/usage_error.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {

const Option& Values::option(const std::string& name) const {
  const Option* o = table_->find(name);
  if (!o) throw std::logic_error(table_->name + " has no option " + name);
  return *o;
}

void Values::set(const std::string& name, std::string text) {
  const Option& o = option(name);
  if (const std::string why = o.check(text); !why.empty()) throw UsageError(option_word(o.name) + ": " + why);
  auto& slot = given_[o.name];
  if (o.kind != OptionKind::repeated) slot.clear();
  slot.push_back(std::move(text));
}

void Values::set_flag(const std::string& name, bool on) {
  const Option& o = option(name);
  given_[o.name] = {on ? "1" : "0"};
}

bool Values::given(const std::string& name) const { return given_.count(option(name).name) > 0; }

std::string Values::text(const std::string& name) const {
  const Option& o = option(name);
  const auto it = given_.find(o.name);
  if (it != given_.end() && !it->second.empty()) return it->second.back();
  return o.fallback == kRequired ? "" : o.fallback;
}

long long Values::integer(const std::string& name) const {
  long long x = 0;
  const std::string t = text(name);
  if (!read_integer(t, x)) throw std::logic_error(name + ": no integer default in the table");
  return x;
}

double Values::number(const std::string& name) const {
  double x = 0;
  const std::string t = text(name);
  if (!read_number(t, x)) throw std::logic_error(name + ": no number default in the table");
  return x;
}

bool Values::flag(const std::string& name) const { return text(name) == "1"; }

std::vector<std::string> Values::list(const std::string& name) const {
  const auto it = given_.find(option(name).name);
  return it == given_.end() ? std::vector<std::string>{} : it->second;
}

namespace {

// One file by two names: equal once made absolute and normal (of a file not yet there), or the same
// file (a link, a folder named two ways).
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec, ec2;
  if (a == b) return true;
  const fs::path pa = fs::weakly_canonical(a, ec).lexically_normal(),
                 pb = fs::weakly_canonical(b, ec2).lexically_normal();
  if (!ec && !ec2 && pa == pb) return true;
  return fs::equivalent(a, b, ec);
}

}  // namespace

void check_distinct_outputs(const Values& v) {
  std::vector<const Option*> outputs;
  for (const auto& o : v.table().options)
    if (o.writes_file && v.given(o.name) && v.text(o.name) != "-") outputs.push_back(&o);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (same_file(v.text(outputs[i]->name), v.text(outputs[j]->name)))
        throw UsageError(outputs[i]->name + " and " + outputs[j]->name + " name the same file '" +
                         display_name(v.text(outputs[j]->name)) + "': each output needs its own file");
}

}  // namespace scalcal::commands
