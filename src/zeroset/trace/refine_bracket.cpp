// Refinement through roots/refine.hpp's guarded Newton.
#include "zeroset/trace/refine_bracket.hpp"

#include <cmath>

#include "zeroset/roots/refine.hpp"

namespace zeroset {

std::optional<double> refine_sign_change(RayFunction& h, double a, double b, TraceCounters& counters) {
    auto h_and_slope = [&](double t) {
        const Jet<double> j = h.jet(t, counters);
        return ValueAndDerivative{j.v, j.d1};
    };
    const BracketResult r = refine_root(h_and_slope, a, b);
    if (r.status != BracketStatus::Converged) return std::nullopt;
    return r.t;
}

std::optional<double> finest_segment_hit(RayFunction& h, double a, double b, const Interval& slope,
                                         TraceCounters& counters) {
    const bool bounded = !slope.is_empty() && std::isfinite(slope.lo) && std::isfinite(slope.hi);
    if (bounded) return a;
    if (!(h.value(a, counters) > 0.0) || !(h.value(b, counters) > 0.0)) return a;
    return std::nullopt;
}

}  // namespace zeroset
