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
    options.domain = Interval(span.t0, span.t1);
    options.iterates = settings_.log ? &settings_.log->newton_iterates : nullptr;
    const NewtonResult r = newton(h_and_slope, settings_.newton_start.value_or(span.t0), options);
    switch (r.status) {
        case NewtonStatus::Converged: return {r.t, HitStatus::Ok};
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
