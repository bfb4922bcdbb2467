// Exact linear algebra of the scalar model with GiNaC: the design row h(eta), the moment matrix
// sum_i w_i h_i h_i^T of a weighted point set with exact coordinates (rationals, square roots,
// symbols), and a canonical form that rationalises square roots out of denominators.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace scalcal::symbolic {

using Point = std::array<GiNaC::ex, 3>;

// A position (or an orbit member) with its multiplicity; weights may be symbols.
struct WeightedPoint {
  GiNaC::ex weight;
  Point eta;
};

// h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx) as a 9x1 matrix.
GiNaC::matrix design_row(const Point& eta);

// sum_i w_i h(eta_i) h(eta_i)^T with every entry in canonical form (see canonical()).
GiNaC::matrix moment_matrix(const std::vector<WeightedPoint>& points);

// sum_i w_i x^a y^b z^c over a program, exactly (canonical): what any model's moment matrix is
// made of, whatever its monomials (symbolic/model_moments.hpp).
using MomentFunction = std::function<GiNaC::ex(int a, int b, int c)>;
MomentFunction point_moments(std::vector<WeightedPoint> points);

// Expanded numerator over a denominator free of square roots of numbers: two equal elements of
// Q(sqrt p, sqrt q, ...)(symbols) then print alike, and a zero test is `canonical(x).is_zero()`.
GiNaC::ex canonical(const GiNaC::ex& e);

// The text of an expression for output: the same expression prints the same bytes on every run
// (scalcal's reproducibility rule), whatever GiNaC's internal term order. The form is kept
// (factored stays factored) and GiNaC's parser reads it back. Sums are expanded, terms ordered by
// degree in the symbols, then by symbol names, then radicals, then coefficient; products print the
// number first, then radicals, constants, symbols (by name), functions and sums; a sum raised to
// an integer power in a product has its sign and rational content moved to the number:
//   1889568*(2*a+e)^(-2)*(3*a+4*d+6*e)^5*(8*d+9*e)^(-3),   45+18*sqrt(2).
std::string canonical_text(const GiNaC::ex& e);

// e with every real float replaced by the simplest fraction within its precision (0.1 -> 1/10): a
// decimal the user typed (0.5, 1.) stands for the exact number it names. GiNaC's floats made the
// closed forms depend on rounding: a denominator could cancel to zero, and the printed forms varied
// from run to run (the fuzzer found both).
GiNaC::ex exact_decimals(const GiNaC::ex& e);

// An angle in degrees reduced exactly modulo 360 into [0, 360), before it becomes radians: a decimal
// literal by its text (1e20 is 10^20, 280 modulo 360, whatever a float of it would hold), any other
// number by the value it holds (a fraction exactly, a float's binary value exactly). The result is
// exact when the number was (an integer or fraction), a float when it was a float (a literal with a
// point or an exponent); anything that is not a real number is returned as it is.
GiNaC::ex reduced_degrees(const GiNaC::ex& value, const std::string& text);

// True when e is provably zero after canonical().
inline bool is_zero_exact(const GiNaC::ex& e) { return canonical(e).is_zero(); }

// Degree of the monomial h_r in the coordinates: 1 for bias rows, 2 for the others.
inline int row_degree(int r) { return r < 3 ? 1 : 2; }

}  // namespace scalcal::symbolic
