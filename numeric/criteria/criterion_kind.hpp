// The four optimality criteria of the paper, by name: D (det K), A (trace K), E (max eigenvalue
// of K) and S (max diagonal element of K, the paper's Xi_sigma / Table 3's Xi_B).
#pragma once
#include <array>
#include <optional>
#include <string_view>

namespace scalcal {

enum class CriterionKind { D, A, E, S };

inline constexpr std::array<CriterionKind, 4> kCriteria = {CriterionKind::D, CriterionKind::A, CriterionKind::E,
                                                           CriterionKind::S};

constexpr std::string_view criterion_name(CriterionKind c) {
  switch (c) {
    case CriterionKind::D: return "D";
    case CriterionKind::A: return "A";
    case CriterionKind::E: return "E";
    case CriterionKind::S: return "S";
  }
  return "?";
}

constexpr std::optional<CriterionKind> parse_criterion(std::string_view s) {
  for (auto c : kCriteria)
    if (criterion_name(c) == s) return c;
  return std::nullopt;
}

}  // namespace scalcal
