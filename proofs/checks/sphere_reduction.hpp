// GiNaC helpers the model limit checks share: a polynomial reduced modulo x^2 + y^2 + z^2 = 1 (so
// an identity on the sphere is a zero test), the quadratic form h^T Q h, and s I.
#pragma once
#include <ginac/ginac.h>

namespace scalcal::proofs {

// The unique form p0(x, y) + z p1(x, y) of e modulo x^2 + y^2 + z^2 = 1.
inline GiNaC::ex on_sphere(const GiNaC::ex& e, const GiNaC::symbol& x, const GiNaC::symbol& y, const GiNaC::symbol& z) {
  GiNaC::ex p = GiNaC::expand(e);
  for (int pass = 0; pass < 20; ++pass) {
    const GiNaC::ex q = GiNaC::expand(p.subs(GiNaC::pow(z, 2) == 1 - x * x - y * y, GiNaC::subs_options::algebraic));
    if (q.is_equal(p)) break;
    p = q;
  }
  return p;
}

inline GiNaC::ex quad(const GiNaC::matrix& h, const GiNaC::matrix& Q) { return h.transpose().mul(Q).mul(h)(0, 0); }

inline GiNaC::matrix scaled_identity(int n, const GiNaC::ex& s) {
  GiNaC::matrix I(n, n);
  for (int i = 0; i < n; ++i) I(i, i) = s;
  return I;
}

}  // namespace scalcal::proofs
