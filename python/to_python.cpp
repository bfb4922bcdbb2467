#include "python/to_python.hpp"

#include <cstdint>
#include <optional>
#include <vector>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace scalcal::python {
namespace {

using commands::Json;

// The shape of a non-empty array of numbers (rank 1) or of equal-length non-empty arrays of numbers
// (rank 2); nothing for any other array (empty, mixed, ragged, holding null or objects).
std::optional<std::vector<py::ssize_t>> numeric_shape(const Json& a, bool& integral) {
  if (a.empty()) return std::nullopt;
  integral = true;
  const auto scalar = [&](const Json& v) {
    if (!v.is_number()) return false;
    if (v.is_number_float()) integral = false;
    return true;
  };
  if (a.front().is_array()) {
    const std::size_t cols = a.front().size();
    if (cols == 0) return std::nullopt;
    for (const auto& row : a) {
      if (!row.is_array() || row.size() != cols) return std::nullopt;
      for (const auto& v : row)
        if (!scalar(v)) return std::nullopt;
    }
    return std::vector<py::ssize_t>{static_cast<py::ssize_t>(a.size()), static_cast<py::ssize_t>(cols)};
  }
  for (const auto& v : a)
    if (!scalar(v)) return std::nullopt;
  return std::vector<py::ssize_t>{static_cast<py::ssize_t>(a.size())};
}

template <class T>
py::array filled(const Json& a, const std::vector<py::ssize_t>& shape) {
  py::array_t<T> out(shape);
  T* p = out.mutable_data();
  for (const auto& v : a) {
    if (v.is_array())
      for (const auto& x : v) *p++ = x.get<T>();
    else
      *p++ = v.get<T>();
  }
  return out;
}

}  // namespace

namespace {
// A string that is not valid UTF-8 (a file name in another encoding) keeps its bad bytes as
// surrogates, Python's own convention for such names (os.fsdecode), instead of raising.
py::str text(const std::string& s) {
  PyObject* o = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "surrogateescape");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}
}  // namespace

py::object to_python(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case Json::value_t::number_float:
      return py::float_(value.get<double>());
    case Json::value_t::string:
      return text(value.get<std::string>());
    case Json::value_t::array: {
      bool integral = false;
      if (const auto shape = numeric_shape(value, integral))
        return integral ? filled<std::int64_t>(value, *shape) : filled<double>(value, *shape);
      py::list list;
      for (const auto& v : value) list.append(to_python(v));
      return list;
    }
    case Json::value_t::object: {
      py::dict dict;
      for (const auto& [key, v] : value.items()) dict[text(key)] = to_python(v);
      return dict;
    }
    default:
      return py::none();  // binary and discarded values never occur in a report
  }
}

}  // namespace scalcal::python
