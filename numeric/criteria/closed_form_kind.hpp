// Which closed form of K a criterion's exact value is (symbolic/criteria.cpp writes it in GiNaC): named here,
// without GiNaC, so that a criterion's type states it beside its value and the symbolic side never chooses by
// the criterion's name. A criterion that names none has no closed form (`family` and `jig` then give numbers).
#pragma once

namespace scalcal {

enum class ClosedFormKind {
  None,
  PowerOverDeterminant,  // N^P / det M = N^P det K
  TraceOfK,              // N tr K
  LargestEigenvalueOfK,  // N lambda_max(K) = N / lambda_min(M)
  LargestDiagonalOfK,    // N max_r K(r,r)
};

// C::closed_form, or None for a criterion type that states none.
template <class C>
constexpr ClosedFormKind closed_form_kind() {
  if constexpr (requires { C::closed_form; }) return C::closed_form;
  return ClosedFormKind::None;
}

}  // namespace scalcal
