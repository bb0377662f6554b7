// Newton's method over roots/newton.hpp, with the span as its domain.
#include "zeroset/trace/newton_method.hpp"

#include "zeroset/roots/newton.hpp"

namespace zeroset {

HitResult NewtonMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    auto h_and_slope = [&](double t) {
        const Jet<double> j = h.jet(t, counters);
        return ValueAndDerivative{j.v, j.d1};
    };
    NewtonOptions options;
    options.max_iterations = settings_.newton_max_iterations;
    // Iterates may wander outside the span and come back, as in Fig. 4 (from
    // 3.6 the survey's Newton passes t ≈ 1.96 on its way to the third root);
    // leaving the span widened by its own length on each side is divergence.
    const double reach = span.t1 - span.t0;
    options.domain = Interval(span.t0 - reach, span.t1 + reach);
    options.iterates = settings_.log ? &settings_.log->newton_iterates : nullptr;
    const NewtonResult r = newton(h_and_slope, settings_.newton_start.value_or(span.t0), options);
    switch (r.status) {
        case NewtonStatus::Converged:
            if (r.t < span.t0 || r.t > span.t1) return {std::nullopt, HitStatus::NoHit};  // a root outside the bounds
            return {r.t, HitStatus::Ok};
        case NewtonStatus::Diverged: return {std::nullopt, HitStatus::Diverged};
        case NewtonStatus::Stalled:
        case NewtonStatus::MaxIterations: break;
    }
    return {std::nullopt, HitStatus::Failed};
}

HitStatus NewtonMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    const HitResult r = first_hit(h, span, counters);
    if (r.t) hits.push_back(*r.t);
    return r.status;
}

}  // namespace zeroset
