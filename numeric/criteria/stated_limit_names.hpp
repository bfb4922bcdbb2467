// Where the models' stated limits meet the criteria's list: a model (numeric/model/, before the criteria in the
// folders' order) names the criterion of each limit it states as text ("D"), so nothing there can check the name.
// Here it is checked against the registered criteria, at compile time (stated_limit_names.cpp asserts it for every
// registered model): a misspelt or unregistered name, or two limits for one criterion, would be a limit never read.
#pragma once
#include <cstddef>
#include <string_view>

#include "numeric/criteria/registry.hpp"

namespace scalcal {

namespace detail {
template <class... Cs>
consteval bool names_a_criterion(std::string_view name, TypeList<Cs...>) {
  return ((Cs::name == name) || ...);
}
}  // namespace detail

// Whether every limit model M states names a registered criterion, each at most once (true for a model stating none).
template <class M>
consteval bool stated_limits_name_criteria() {
  if constexpr (requires { M::limits; }) {
    for (std::size_t i = 0; i < M::limits.size(); ++i) {
      if (!detail::names_a_criterion(M::limits[i].criterion, RegisteredCriteria{})) return false;
      for (std::size_t j = 0; j < i; ++j)
        if (M::limits[j].criterion == M::limits[i].criterion) return false;
    }
  }
  return true;
}

}  // namespace scalcal
