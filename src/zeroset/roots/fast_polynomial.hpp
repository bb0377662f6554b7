// The fast polynomial solver of Yuksel, "High-Performance Polynomial Root
// Finding for Graphics" (HPG 2022), a modern answer to the survey's §3.4
// (whose all-roots methods "are usually the least efficient"). The roots of
// p′ split [t0, t1] into intervals where p is monotone, so each interval holds
// at most one root, and only when p changes sign across it; that root is
// found by safeguarded Newton. p′'s roots come the same way from
// p″, down to a quadratic solved in closed form. All derivatives are built
// up front in fixed arrays: nothing is allocated.
//
// Guaranteed up to rounding: a point where |p| is below the rounding-error
// bound of its Horner evaluation counts as a root (so a double root, where
// p′ = 0 and p does not change sign, is reported at p′'s root), and a run of
// such points — a cluster or higher multiplicity — is reported once.
#pragma once

#include <span>

#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

/// The real roots of the polynomial c (ascending powers, degree ≤ 32) in
/// [t0, t1], increasing, into out (at most out.size() of them: the first
/// ones). The zero polynomial and constants have none.
PolynomialRoots fast_polynomial_roots(std::span<const double> c, double t0, double t1, std::span<double> out);

/// The roots of c′ in [t0, t1] — the extrema of c there — increasing, into
/// out, which must hold degree − 1 of them (a constant or a line has none).
PolynomialRoots fast_polynomial_extrema(std::span<const double> c, double t0, double t1, std::span<double> out);

/// The smallest real root in [t0, t1].
inline FirstPolynomialRoot fast_polynomial_first_root(std::span<const double> c, double t0, double t1) {
    return first_root_with(fast_polynomial_roots, c, t0, t1);
}

}  // namespace zeroset
