// Laguerre's method for all the roots of a polynomial (survey §3.4: reported
// in Wyvill & Trotman 1990; the algorithm of Numerical Recipes §9.5, written
// anew): each root of the deflated polynomial is found by Laguerre's
// iteration in complex arithmetic from 0, polished against the original
// polynomial, and divided out. The real ones in [t0, t1] are kept: a root
// whose imaginary part is below laguerre_real_tolerance times max(1, |re|).
//
// NOT guaranteed: it converges from almost any start but may stop short of a
// root, deflation error can merge or move close roots, and a double root
// comes out as two nearby reals or a complex pair with a tiny imaginary part
// (kept by the tolerance, so it appears twice). A near miss whose complex
// pair lies within the tolerance of the real axis is reported as a root.
// Every root is found, real or not, which is why the survey calls such
// methods the least efficient for ray tracing.
#pragma once

#include <span>

#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {

inline constexpr double laguerre_real_tolerance = 1e-6;

/// The real roots of c (ascending powers, degree ≤ 32) in [t0, t1],
/// increasing, into out (at most out.size() of them: the first ones).
PolynomialRoots laguerre_roots(std::span<const double> c, double t0, double t1, std::span<double> out);

/// The smallest real root in [t0, t1].
inline FirstPolynomialRoot laguerre_first_root(std::span<const double> c, double t0, double t1) {
    return first_root_with(laguerre_roots, c, t0, t1);
}

}  // namespace zeroset
