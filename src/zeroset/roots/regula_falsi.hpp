// Regula falsi on a sign-change bracket (survey §2; after Descartes' rule it
// is Hanrahan's refinement step, §3.4): split the bracket where the secant
// through its ends crosses zero. Plain regula falsi keeps one end fixed on a
// convex function and crawls. This is the Anderson–Björck variant: when the
// same end is replaced twice in a row, the value the secant uses for the end
// that stayed is scaled by m = 1 − H(c)/H(b) (b the end just replaced, c its
// replacement), or by ½ — the Illinois factor — when m ≤ 0. The kept end then
// moves soon and convergence on simple roots is superlinear.
//
// Safeguards: a secant point rounded onto an end of the bracket becomes the
// next double inside (the root is within an ulp of that end, so this probe
// closes the bracket); a NaN one (overflow) becomes the midpoint; and the
// guard of bracket.hpp bisects whenever three steps fail to halve the
// bracket. It runs to full double precision. On multiple roots, where H is
// flat and secants barely move, it is a few times slower than bisection.
//
// Like bisection it finds *a* root of the bracket, not necessarily the first
// one along the ray: that is what isolation is for.
#pragma once

#include <cmath>

#include "zeroset/roots/bracket.hpp"
#include "zeroset/roots/root_function.hpp"

namespace zeroset {

namespace detail {
/// The Anderson–Björck factor for the end that stayed, when the other end b
/// (with value h_b) was just replaced by c (with value h_c, same sign).
inline double anderson_bjorck(double h_c, double h_b) {
    const double m = 1.0 - h_c / h_b;
    return m > 0.0 ? m : 0.5;
}
}  // namespace detail

/// A root of h in [a, b], where h(a) and h(b) lie on opposite sides of the
/// surface (H ≤ 0 inside) or one of them is exactly 0 (a, the lower end, wins).
template <ScalarFunction F>
BracketResult regula_falsi(F&& h, double a, double b, const BracketOptions& options = {}) {
    BracketSearch search(h, a, b);
    double lo_weight = 1.0;  // the factors the secant applies to H at each end
    double hi_weight = 1.0;
    BracketEnd last_moved = BracketEnd::None;
    while (search.running(options)) {
        double t = search.midpoint();
        if (!search.must_bisect()) {
            const double h_lo = lo_weight * search.lo().h.value;
            const double h_hi = hi_weight * search.hi().h.value;
            // h_lo and h_hi differ in sign, so the fraction lies in [0, 1].
            const double lo = search.lo().t;
            const double hi = search.hi().t;
            const double secant = lo + (hi - lo) * (h_lo / (h_lo - h_hi));
            // A secant point rounded onto an end says the root is within an
            // ulp of it: probe the next double, which closes the bracket.
            if (secant <= lo) t = std::nextafter(lo, hi);
            else if (secant >= hi) t = std::nextafter(hi, lo);
            else if (search.strictly_inside(secant)) t = secant;
        }
        const double replaced_lo = search.lo().h.value;
        const double replaced_hi = search.hi().h.value;
        const BracketEnd moved = search.step(h, t);
        if (moved == BracketEnd::Lo) {
            if (last_moved == BracketEnd::Lo) hi_weight *= detail::anderson_bjorck(search.lo().h.value, replaced_lo);
            lo_weight = 1.0;
        } else if (moved == BracketEnd::Hi) {
            if (last_moved == BracketEnd::Hi) lo_weight *= detail::anderson_bjorck(search.hi().h.value, replaced_hi);
            hi_weight = 1.0;
        }
        last_moved = moved;
    }
    return search.result(options);
}

}  // namespace zeroset
