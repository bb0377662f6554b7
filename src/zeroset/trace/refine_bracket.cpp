// Refinement through roots/refine.hpp's guarded Newton.
#include "zeroset/trace/refine_bracket.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "zeroset/roots/refine.hpp"

namespace zeroset {

std::optional<double> refine_sign_change(RayFunction& h, double a, double b, TraceCounters& counters) {
    auto h_and_slope = [&](double t) {
        const Jet<double> j = h.jet(t, counters);
        return ValueAndDerivative{j.v, j.d1};
    };
    // The ends start with H alone (H′ NaN), so the first step is regula
    // falsi's (roots/refine.hpp) and jets are spent inside only. H there is
    // usually known already — a march has just taken it at both ends of the
    // bracket it found — and the refinement is the same whether it is.
    if (b < a) std::swap(a, b);
    if (!std::isfinite(a) || !std::isfinite(b)) return std::nullopt;
    const auto end = [&](double t) {
        return BracketPoint{t, {h.value(t, counters), std::numeric_limits<double>::quiet_NaN()}};
    };
    const BracketResult r = refine_root(h_and_slope, end(a), end(b));
    if (r.status != BracketStatus::Converged) return std::nullopt;
    return r.t;
}

bool closes_in_on_a_pole(RayFunction& h, double a, double b, TraceCounters& counters) {
    double lo = a, hi = b, f_lo = h.value(a, counters), f_hi = h.value(b, counters);
    if (std::isnan(f_lo) || std::isnan(f_hi)) return false;
    // Bisect a sign change between finite values down to adjacent doubles
    // (64 halvings are more than any double interval needs) …
    const bool negative_lo = f_lo < 0.0;
    for (int i = 0; i < 64 && std::isfinite(f_lo) && std::isfinite(f_hi) && negative_lo != (f_hi < 0.0); ++i) {
        const double mid = 0.5 * lo + 0.5 * hi;
        if (!(lo < mid && mid < hi)) break;
        const double f = h.value(mid, counters);
        if (std::isnan(f)) return false;
        ((f < 0.0) == negative_lo ? lo : hi) = mid;
        ((f < 0.0) == negative_lo ? f_lo : f_hi) = f;
    }
    // … and compare |H| there with |H| a little way off on either side. The
    // probes may leave the span, and the object's domain: a NaN there is not
    // the surface's, so it is not recorded. They also leave the box a pruned
    // tape is valid in, so they use the full tape (the caller's next prune
    // binds its own again).
    h.use_full_tape();
    const double w = 16.0 * (b - a);
    const std::uint64_t nans = counters.nan_evaluations;
    const double off = std::max(std::abs(h.value(a - w, counters)), std::abs(h.value(b + w, counters)));
    counters.nan_evaluations = nans;
    return std::isfinite(off) && std::min(std::abs(f_lo), std::abs(f_hi)) > off;
}

std::optional<double> finest_segment_hit(RayFunction& h, double a, double b, const Jet<Interval>& e,
                                         TraceCounters& counters) {
    const auto bounded = [](const Interval& x) { return !x.is_empty() && std::isfinite(x.lo) && std::isfinite(x.hi); };
    const double fa = h.value(a, counters), fb = h.value(b, counters);
    if (std::isnan(fa) || std::isnan(fb)) return std::nullopt;  // H undefined: no root (the caller fails)
    if (bounded(e.d1)) return a;
    if (fa > 0.0 && fb > 0.0) return std::nullopt;  // no sign at the ends shows a root
    // Where the enclosure of H is unbounded too, a sign change may be a pole.
    if (!bounded(e.v) && closes_in_on_a_pole(h, a, b, counters)) return std::nullopt;
    return a;
}

}  // namespace zeroset
