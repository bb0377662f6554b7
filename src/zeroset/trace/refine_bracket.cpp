// Refinement through roots/refine.hpp's guarded Newton.
#include "zeroset/trace/refine_bracket.hpp"

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

}  // namespace zeroset
