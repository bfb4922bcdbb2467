#include "experiments/json.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace scalcal::cli {

Json& Json::set(const std::string& key, Json value) {
  auto& obj = std::get<Object>(v_);
  for (auto& kv : obj)
    if (kv.first == key) {
      kv.second = std::move(value);
      return *this;
    }
  obj.emplace_back(key, std::move(value));
  return *this;
}

Json& Json::push(Json value) {
  std::get<Array>(v_).push_back(std::move(value));
  return *this;
}

std::string Json::str(int indent) const {
  std::ostringstream s;
  dump(s, indent);
  return s.str();
}

namespace {

void write_string(std::ostream& out, const std::string& s) {
  out << '"';
  for (char c : s) {
    switch (c) {
      case '"': out << "\\\""; break;
      case '\\': out << "\\\\"; break;
      case '\n': out << "\\n"; break;
      case '\t': out << "\\t"; break;
      case '\r': out << "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out << buf;
        } else {
          out << c;
        }
    }
  }
  out << '"';
}

void newline(std::ostream& out, int indent, int depth) {
  if (indent <= 0) return;
  out << '\n' << std::string(static_cast<std::size_t>(indent * depth), ' ');
}

}  // namespace

void Json::write(std::ostream& out, int indent, int depth) const {
  if (std::holds_alternative<std::nullptr_t>(v_)) {
    out << "null";
  } else if (auto b = std::get_if<bool>(&v_)) {
    out << (*b ? "true" : "false");
  } else if (auto i = std::get_if<long long>(&v_)) {
    out << *i;
  } else if (auto d = std::get_if<double>(&v_)) {
    if (!std::isfinite(*d)) {
      out << "null";
    } else {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", *d);
      out << buf;
    }
  } else if (auto s = std::get_if<std::string>(&v_)) {
    write_string(out, *s);
  } else if (auto a = std::get_if<Array>(&v_)) {
    // An array of scalars stays on one line: programs print as rows of [x, y, z].
    bool flat = true;
    for (const auto& e : *a)
      if (std::holds_alternative<Array>(e.v_) || std::holds_alternative<Object>(e.v_)) flat = false;
    out << '[';
    for (std::size_t k = 0; k < a->size(); ++k) {
      if (k) out << (flat ? ", " : ",");
      if (!flat) newline(out, indent, depth + 1);
      (*a)[k].write(out, indent, depth + 1);
    }
    if (!flat && !a->empty()) newline(out, indent, depth);
    out << ']';
  } else {
    const auto& o = std::get<Object>(v_);
    out << '{';
    for (std::size_t k = 0; k < o.size(); ++k) {
      if (k) out << ',';
      newline(out, indent, depth + 1);
      write_string(out, o[k].first);
      out << (indent > 0 ? ": " : ":");
      o[k].second.write(out, indent, depth + 1);
    }
    if (!o.empty()) newline(out, indent, depth);
    out << '}';
  }
}

}  // namespace scalcal::cli
