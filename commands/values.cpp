// Values of a command's options (values.hpp).
#include "commands/values.hpp"

#include <stdexcept>

#include "commands/usage_error.hpp"

namespace scalcal::commands {

const Option& Values::option(const std::string& name) const {
  const Option* o = table_->find(name);
  if (!o) throw std::logic_error(table_->name + " has no option " + name);
  return *o;
}

void Values::set(const std::string& name, std::string text) {
  const Option& o = option(name);
  if (const std::string why = o.check(text); !why.empty()) throw UsageError(o.name + ": " + why);
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

}  // namespace scalcal::commands
