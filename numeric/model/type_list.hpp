// What the registries of models and criteria share: a list of types, the index of a type in it, and
// the one place where a runtime index meets the templates (f(T{}) for the index's type). Written once
// for both registries.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace scalcal {

template <class... Ts>
struct TypeList {
  static constexpr int size = sizeof...(Ts);
};

namespace detail {

// The index of T in the list; -1 when T is not there.
template <class T, class... Ts>
constexpr int index_in(TypeList<Ts...>) {
  int i = 0, found = -1;
  ((std::is_same_v<T, Ts> ? (found = i, ++i) : ++i), ...);
  return found;
}

// f(T{}) for the index-th type of the list; every type must give f the same result type.
template <class F, class First, class... Ts>
auto visit_index(int index, F&& f, const char* what, TypeList<First, Ts...>) {
  using R = decltype(f(First{}));
  if (index < 0 || index > static_cast<int>(sizeof...(Ts)))
    throw std::out_of_range(std::string(what) + ": no such index " + std::to_string(index));
  if constexpr (std::is_void_v<R>) {
    int i = 0;
    (void)(i++ == index ? (void)f(First{}) : (void)0);
    ((i++ == index ? (void)f(Ts{}) : (void)0), ...);
  } else {
    std::optional<R> out;
    int i = 0;
    (void)(i++ == index ? (void)out.emplace(f(First{})) : (void)0);
    ((i++ == index ? (void)out.emplace(f(Ts{})) : (void)0), ...);
    return R(std::move(*out));
  }
}

}  // namespace detail
}  // namespace scalcal
