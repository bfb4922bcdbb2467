// Theorem 4 (A, E, S limits): for the symmetric measure, the pieces of each criterion as
// functions of b, their exact minimisers over (0, 1/9), and agreement with numeric/limits.hpp.
#include "numeric/criteria/registry.hpp"
#include "proofs/checks/check.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::CriterionKind;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {
bool same_set(std::vector<ex> got, std::vector<ex> want) {
  if (got.size() != want.size()) return false;
  for (const auto& w : want) {
    bool found = false;
    for (const auto& g : got) found = found || sym::is_zero_exact(g - w);
    if (!found) return false;
  }
  return true;
}
}  // namespace

int main() {
  const symbol b("b");
  const ex q = ex(1) / 3 - 3 * b;  // the double eigenvalue of the squares block
  check(same_set(sym::criterion_pieces(CriterionKind::A, b), {12 + 2 / q + 3 / b}),
        "A(b) = 9 + 3 + 2/(1/3 - 3b) + 3/b");
  check(same_set(sym::criterion_pieces(CriterionKind::E, b), {ex(3), 1 / q, 1 / b}),
        "E(b) = max(3, 1/(1/3 - 3b), 1/b)");
  check(same_set(sym::criterion_pieces(CriterionKind::S, b), {ex(3), (1 - 3 * b) / q, 1 / b}),
        "S(b) = max(3, (1 - 3b)/(1/3 - 3b), 1/b)");
  GiNaC::parser reader;
  for (auto c : {CriterionKind::A, CriterionKind::E, CriterionKind::S}) {
    const auto lim = sym::symbolic_limit(c);
    const auto stated = scalcal::criterion_limit<double>(c);
    const std::string name(scalcal::criterion_name(c));
    std::cout << "  " << name << ": " << sym::canonical_text(lim.value) << " at b = " << sym::canonical_text(lim.b)
              << "\n";
    check(sym::is_zero_exact(reader(std::string(stated.exact)) - lim.value),
          (name + ": numeric/limits.hpp exact value agrees").c_str());
    check(std::abs(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(lim.b)).to_double() - stated.moment_b) < 1e-15,
          (name + ": numeric/limits.hpp moment b agrees").c_str());
  }
  check(sym::is_zero_exact(sym::symbolic_limit(CriterionKind::A).value - (45 + 18 * GiNaC::sqrt(ex(2)))),
        "A limit = 45 + 18 sqrt 2");
  check(sym::is_zero_exact(sym::symbolic_limit(CriterionKind::E).value - 12), "E limit = 12");
  check(sym::is_zero_exact(sym::symbolic_limit(CriterionKind::S).value - (6 + 3 * GiNaC::sqrt(ex(3)))),
        "S limit = 6 + 3 sqrt 3");
  return scalcal::proofs::finish();
}
