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

std::optional<double> finest_segment_hit(RayFunction& h, double a, double b, const Jet<Interval>& e,
                                         TraceCounters& counters) {
    const auto bounded = [](const Interval& x) { return !x.is_empty() && std::isfinite(x.lo) && std::isfinite(x.hi); };
    if (bounded(e.d1)) return a;
    if (!bounded(e.v)) return std::nullopt;  // a pole
    if (!(h.value(a, counters) > 0.0) || !(h.value(b, counters) > 0.0)) return a;
    return std::nullopt;
}

}  // namespace zeroset
