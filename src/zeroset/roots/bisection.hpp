// Bisection on a sign-change bracket, to full double precision. This is the
// algorithm the survey prints as Figure 6 (§2): halve [t₀, t₁] at t_m, return
// t_m when H(t_m) = 0, keep the half whose ends differ in sign. The figure is
// captioned "regula falsi", but what it shows is bisection — regula falsi
// proper, which splits at the secant's zero, is in regula_falsi.hpp.
//
// Slow (one bit per evaluation) but it cannot fail on a valid bracket: it
// stops after at most max_bisections steps, when the midpoint equals an end.
#pragma once

#include "zeroset/roots/bracket.hpp"
#include "zeroset/roots/root_function.hpp"

namespace zeroset {

/// A root of h in [a, b], where h(a) and h(b) lie on opposite sides of the
/// surface (H ≤ 0 inside) or one of them is exactly 0 (a, the lower end, wins).
template <ScalarFunction F>
BracketResult bisection(F&& h, double a, double b, const BracketOptions& options = {}) {
    BracketSearch search(h, a, b);
    while (search.running(options)) search.step(h, search.midpoint());
    return search.result(options);
}

}  // namespace zeroset
