// Guarded Newton on a sign-change bracket: a Newton step is taken when it
// lands strictly inside the bracket, otherwise the bracket is bisected; the
// bracket shrinks every step, so refinement ends at adjacent doubles.
#include "zeroset/trace/refine_bracket.hpp"

#include <cmath>

namespace zeroset {

std::optional<double> refine_sign_change(RayFunction& h, double a, double b, TraceCounters& counters) {
    double fa = h.value(a, counters);
    if (fa == 0.0) return a;
    double fb = h.value(b, counters);
    if (fb == 0.0) return b;
    if (std::isnan(fa) || std::isnan(fb) || (fa < 0.0) == (fb < 0.0)) return std::nullopt;
    double t = 0.5 * (a + b);
    for (int i = 0; i < 200; ++i) {
        const Jet<double> j = h.jet(t, counters);
        if (std::isnan(j.v)) return std::nullopt;
        if (j.v == 0.0) return t;
        // Keep the sign change inside [a, b].
        if ((j.v < 0.0) == (fa < 0.0)) {
            a = t;
            fa = j.v;
        } else {
            b = t;
        }
        const double newton = t - j.v / j.d1;
        const double mid = 0.5 * (a + b);
        const double next = (newton > a && newton < b) ? newton : mid;
        if (next <= a || next >= b || mid <= a || mid >= b) break;  // a and b are adjacent doubles
        t = next;
    }
    // The end where H has the sign of the solid's side is within an ulp of the root.
    return std::abs(fa) <= std::abs(h.value(b, counters)) ? a : b;
}

}  // namespace zeroset
