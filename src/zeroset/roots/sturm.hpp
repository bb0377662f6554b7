// Sturm sequences (survey §3.4: van Wijk 1984 solved his swept-sphere
// polynomials "by Sturm's method"). p₀ = p, p₁ = p′, pₖ₊₁ = −(pₖ₋₁ mod pₖ);
// the sign changes V(t) along the sequence at t drop by exactly the number of
// distinct real roots in (a, b] from V(a) to V(b). Bisecting by these counts
// isolates every root in [t0, t1]; an interval holding one root whose ends
// differ in sign is refined by safeguarded Newton (refine_root); one without
// a sign change holds a root of even multiplicity, narrowed by counts alone.
//
// In floating point a remainder is only known to within rounding. Each
// member carries a running bound on its coefficients' size before
// cancellation (the divisions redone on absolute values); a remainder
// coefficient below sturm_zero_tolerance times both the division's size and
// its own bound is cancellation's residue, and a remainder made of such is
// taken as 0, so the sequence ends at the (numerical) gcd and multiple roots
// count once. A remainder that is merely small, with nothing cancelled
// (t² − 10⁻¹³'s −10⁻¹³), stays. Roots closer together than that resolution
// (about 1e-7 relative) may count as one. A member's leading terms that are
// negligible over the range (cancellation's residue of terms that are 0 in
// exact arithmetic, as in a swept sphere's P) are dropped before it divides:
// dividing by one gave quotients so large that the remainders were noise,
// and a simple root was lost.
#pragma once

#include <span>

#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

/// A remainder coefficient below this times the division's size and the size of what cancelled to make it is 0.
inline constexpr double sturm_zero_tolerance = 1e-13;
/// A member's leading term below this times its largest term over the range
/// counted is dropped before the next division (rounding residue; dividing by
/// it would leave only noise).
inline constexpr double sturm_leading_tolerance = 1e-10;

/// The distinct real roots of c (ascending powers, degree ≤ 32) in [t0, t1],
/// increasing, into out (at most out.size() of them: the first ones). A
/// cluster that bisection cannot split is reported once, at its midpoint.
PolynomialRoots sturm_roots(std::span<const double> c, double t0, double t1, std::span<double> out);

/// The smallest real root in [t0, t1].
inline FirstPolynomialRoot sturm_first_root(std::span<const double> c, double t0, double t1) {
    return first_root_with(sturm_roots, c, t0, t1);
}

}  // namespace zeroset
