// A minimal JSON value for the CLI's --json output: ordered object keys (so output is stable and
// keys appear in the documented order), doubles at full precision, non-finite numbers as null.
#pragma once
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace scalcal::cli {

class Json {
 public:
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;

  Json() : v_(nullptr) {}
  Json(std::nullptr_t) : v_(nullptr) {}
  Json(bool b) : v_(b) {}
  Json(int i) : v_(static_cast<long long>(i)) {}
  Json(long i) : v_(static_cast<long long>(i)) {}
  Json(long long i) : v_(i) {}
  Json(unsigned long i) : v_(static_cast<long long>(i)) {}
  Json(double d) : v_(d) {}
  Json(const char* s) : v_(std::string(s)) {}
  Json(std::string s) : v_(std::move(s)) {}
  Json(Array a) : v_(std::move(a)) {}

  static Json object() { Json j; j.v_ = Object{}; return j; }
  static Json array() { Json j; j.v_ = Array{}; return j; }
  template <class Range>
  static Json array_of(const Range& r) {
    Json j = array();
    for (const auto& x : r) j.push(Json(x));
    return j;
  }

  // Object: appends (or replaces) a key, keeping insertion order.
  Json& set(const std::string& key, Json value);
  // Array: appends an element.
  Json& push(Json value);

  void dump(std::ostream& out, int indent = 2) const { write(out, indent, 0); }
  std::string str(int indent = 2) const;

 private:
  void write(std::ostream& out, int indent, int depth) const;
  std::variant<std::nullptr_t, bool, long long, double, std::string, Array, Object> v_;
};

}  // namespace scalcal::cli
