// The polish's second-order verdict: first-order conditions cannot tell a minimum from a saddle; the
// interval certificate of certify.hpp can (or proves the limit attained). Which verdict a polished
// program gets, with a true reason, as data for the CLI and the Python module to print.
#pragma once
#include <optional>
#include <string>

#include "numeric/certify/certify.hpp"
#include "numeric/polish/polish.hpp"

namespace scalcal {

struct SecondOrder {
  std::optional<CertifiedStatus> status;  // empty: not checked
  std::string text;                       // status_text(*status), or "not checked (...)"
  std::string reason;                     // certify's reason, or why it did not run
};

// Runs certify on the polished program when the polish converged and the program has at least 9
// positions; a criterion without a known limit or a singular program is "not checked", with why.
SecondOrder second_order(const PolishResult& polished, CriterionKind criterion);

}  // namespace scalcal
