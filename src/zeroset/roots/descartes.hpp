// Root isolation by Descartes' rule of signs (survey §3.4, after Hanrahan
// 1983), in the Bernstein basis (the Vincent–Collins–Akritas method as
// Bernstein subdivision): p on [t0, t1] is written in Bernstein form on
// [0, 1]; the sign variations of its coefficients bound the roots inside and
// have their parity. No variation: no root. One: exactly one root, refined on
// p by safeguarded Newton (refine_root). More: split at ½ with de Casteljau
// and look at the left half first, so roots come out in increasing order.
//
// Rounding: a coefficient within the rounding error of the conversion is
// "zero" and has no sign. An interval whose coefficients are all zero in that
// sense — the polynomial is indistinguishable from 0 there, as it is around a
// double root, a cluster of roots or a grazing near miss — is reported as
// one root at its midpoint; that minimum width is where the recursion stops.
#pragma once

#include <span>

#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

/// The real roots of c (ascending powers, degree ≤ 32) in [t0, t1],
/// increasing, into out (at most out.size() of them: the first ones).
PolynomialRoots descartes_roots(std::span<const double> c, double t0, double t1, std::span<double> out);

/// The smallest real root in [t0, t1].
inline FirstPolynomialRoot descartes_first_root(std::span<const double> c, double t0, double t1) {
    return first_root_with(descartes_roots, c, t0, t1);
}

}  // namespace zeroset
