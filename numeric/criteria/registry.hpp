// The registered criteria: one line each in RegisteredCriteria. A CriterionKind is a runtime handle
// (an index into that list) for the CLI and for results; visit_criterion() turns it back into the
// criterion's type, the one place where a runtime choice meets the templated solvers.
#pragma once
#include <algorithm>
#include <array>
#include <compare>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "numeric/criteria/a_criterion.hpp"
#include "numeric/criteria/closed_form_kind.hpp"
#include "numeric/criteria/d_criterion.hpp"
#include "numeric/criteria/e_criterion.hpp"
#include "numeric/criteria/s_criterion.hpp"
#ifdef SCALCAL_FIFTH_CRITERION
#include "numeric/criteria/integrated_variance.hpp"
#endif
#include "numeric/model/type_list.hpp"

namespace scalcal {

// Every entry must be a Criterion (criterion.hpp): a missing piece is a compile error here.
template <Criterion... Cs>
using CriterionList = TypeList<Cs...>;

#ifdef SCALCAL_FIFTH_CRITERION  // the test build of scripts/fifth_criterion.sh: I as a fifth criterion
using RegisteredCriteria = CriterionList<DCriterion, ACriterion, ECriterion, SCriterion, IntegratedVarianceCriterion>;
#else
using RegisteredCriteria = CriterionList<DCriterion, ACriterion, ECriterion, SCriterion>;
#endif

class CriterionKind {
 public:
  constexpr explicit CriterionKind(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  constexpr auto operator<=>(const CriterionKind&) const = default;

  template <class C>
  static constexpr CriterionKind of() {
    constexpr int i = detail::index_in<C>(RegisteredCriteria{});
    static_assert(i >= 0, "criterion not in RegisteredCriteria");
    return CriterionKind(i);
  }

  // The paper's four criteria, named where the reproduction refers to one of them.
  static const CriterionKind D, A, E, S;

 private:
  int index_;
};

inline constexpr CriterionKind CriterionKind::D = CriterionKind::of<DCriterion>();
inline constexpr CriterionKind CriterionKind::A = CriterionKind::of<ACriterion>();
inline constexpr CriterionKind CriterionKind::E = CriterionKind::of<ECriterion>();
inline constexpr CriterionKind CriterionKind::S = CriterionKind::of<SCriterion>();

namespace detail {
template <class... Cs>
constexpr auto all_kinds(CriterionList<Cs...>) {
  return std::array<CriterionKind, sizeof...(Cs)>{CriterionKind::of<Cs>()...};
}
}  // namespace detail

inline constexpr auto kCriteria = detail::all_kinds(RegisteredCriteria{});
inline constexpr int kCriterionCount = RegisteredCriteria::size;

// f(C{}) for the criterion type C behind c; every registered criterion must give the same type.
template <class F>
auto visit_criterion(CriterionKind c, F&& f) {
  return detail::visit_index(c.index(), std::forward<F>(f), "visit_criterion", RegisteredCriteria{});
}

inline std::string_view criterion_name(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return std::string_view(decltype(C)::name); });
}

// The closed form of K the criterion's exact value is (closed_form_kind.hpp); None for one that states none.
inline ClosedFormKind criterion_closed_form(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return closed_form_kind<decltype(C)>(); });
}

// What scoring one program of the paper's model at N = 12 costs the criterion in CPU seconds, as its type states
// (`scoring_seconds`, measured; commands/core/work_bound prices random search with it). One that states none is
// priced as the dearest that do, so a work bound never undercounts it.
inline double criterion_scoring_seconds(CriterionKind c) {
  const auto stated = [](CriterionKind k) {
    return visit_criterion(k, [](auto C) {
      if constexpr (requires { decltype(C)::scoring_seconds; }) return double(decltype(C)::scoring_seconds);
      return -1.0;
    });
  };
  if (const double s = stated(c); s >= 0) return s;
  double dearest = 0;
  for (int i = 0; i < kCriterionCount; ++i) dearest = std::max(dearest, stated(CriterionKind(i)));
  return dearest;
}

inline std::string_view criterion_summary(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return std::string_view(decltype(C)::summary); });
}

// Its normalised form for tables with P written out ("N^9 det K"), and its unnormalised value's name
// and JSON key ("det K", "det_K").
inline std::string criterion_label(CriterionKind c, int parameters) {
  std::string s(visit_criterion(c, [](auto C) { return std::string_view(decltype(C)::label); }));
  if (const auto at = s.find("^P"); at != std::string::npos) s.replace(at, 2, "^" + std::to_string(parameters));
  return s;
}

inline std::string_view criterion_raw_name(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return std::string_view(decltype(C)::raw_name); });
}

inline std::string_view criterion_raw_key(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return std::string_view(decltype(C)::raw_key); });
}

inline std::optional<CriterionKind> parse_criterion(std::string_view s) {
  for (auto c : kCriteria)
    if (criterion_name(c) == s) return c;
  return std::nullopt;
}

// "D|A|E|S": the registered names, for usage lines.
inline std::string criterion_names(std::string_view separator = "|") {
  std::string out;
  for (auto c : kCriteria) out += (out.empty() ? "" : std::string(separator)) + std::string(criterion_name(c));
  return out;
}

inline ProgramSymmetry symmetry_of(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return decltype(C)::symmetry; });
}

inline int default_starts(CriterionKind c, int positions) {
  return visit_criterion(c, [positions](auto C) { return decltype(C)::default_starts(positions); });
}

template <class Model = Paper9Model, class Scalar = double>
bool has_limit(CriterionKind c) {
  return visit_criterion(c, [](auto C) { return decltype(C)::template limit<Model, Scalar>().has_value(); });
}

// The exact N -> infinity limit of c under the model; throws for a criterion without a known limit.
template <class Scalar = double, class Model = Paper9Model>
CriterionLimitTpl<Scalar> criterion_limit(CriterionKind c) {
  const auto limit = visit_criterion(c, [](auto C) { return decltype(C)::template limit<Model, Scalar>(); });
  if (!limit) throw std::invalid_argument("no known limit for criterion " + std::string(criterion_name(c)));
  return *limit;
}

}  // namespace scalcal
