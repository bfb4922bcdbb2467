// Sturm's theorem for the proof checks: the number of distinct real roots of a polynomial with exact
// coefficients in an interval, so that "p > 0 on [a, b]" is an exact statement (no root there and one
// positive value).
#pragma once
#include <vector>

#include <ginac/ginac.h>

namespace scalcal::proofs {

// Distinct real roots of p (a polynomial in x) in (a, b]: the sign variations of the Sturm chain at a
// minus those at b (exact for distinct roots, whatever p(a), p(b)).
inline int roots_in(const GiNaC::ex& p, const GiNaC::symbol& x, const GiNaC::numeric& a, const GiNaC::numeric& b) {
  std::vector<GiNaC::ex> chain{GiNaC::expand(p), GiNaC::expand(p.diff(x))};
  while (chain.back().degree(x) > 0) {
    const GiNaC::ex r = GiNaC::expand(-GiNaC::rem(chain[chain.size() - 2], chain.back(), x));
    if (r.is_zero()) break;
    chain.push_back(r);
  }
  auto variations = [&](const GiNaC::numeric& at) {
    int count = 0, last = 0;
    for (const GiNaC::ex& q : chain) {
      const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(q.subs(x == at));
      const int s = v.is_zero() ? 0 : (v > 0 ? 1 : -1);
      if (s != 0 && last != 0 && s != last) ++count;
      if (s != 0) last = s;
    }
    return count;
  };
  return variations(a) - variations(b);
}

// p > 0 on [a, b]: p(a) > 0 and no root in (a, b].
inline bool positive_on_closed(const GiNaC::ex& p, const GiNaC::symbol& x, const GiNaC::numeric& a,
                               const GiNaC::numeric& b) {
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::expand(p).subs(x == a)) > 0 && roots_in(p, x, a, b) == 0;
}

}  // namespace scalcal::proofs
