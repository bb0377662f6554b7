// Sphere tracing plus refinement of the stretch it ends on, when the march
// did not refine it itself.
#include "zeroset/trace/sphere_method.hpp"

#include <cmath>

#include "zeroset/trace/refine_bracket.hpp"

namespace zeroset {

namespace {
double far_end(Span span) { return std::max(std::abs(span.t0), std::abs(span.t1)); }
}  // namespace

SphereMethod::SphereMethod(const RootFinderSettings& settings)
    : tracer_({settings.sphere_epsilon, 16, settings.max_segments, settings.tangent_width}),
      close_roots_(settings),
      merge_width_(4.0 * settings.tangent_width),
      max_hits_(settings.max_hits) {}

Crossing SphereMethod::crossing(RayFunction& h, Span span, double side, TraceCounters& counters) {
    const std::uint64_t nans = counters.nan_evaluations;
    return refined(h, tracer_.first_crossing(h, span, side, counters), nans, counters);
}

Crossing SphereMethod::refined(RayFunction& h, const Crossing& marched, std::uint64_t nans, TraceCounters& counters) {
    const std::optional<double> t = marched.t;
    if (!t || counters.nan_evaluations != nans) return {std::nullopt, marched.gave_up};
    if (marched.exact) return marched;
    // The surface is crossed in [t, end], a stretch of the span proven to
    // hold one root (the march's secant probe): refine it to full precision.
    const std::optional<double> root = refine_sign_change(h, *t, marched.end, counters);
    return {root, false, root.value_or(0.0), true};
}

HitResult SphereMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    const double start = h.value(span.t0, counters);
    if (std::isnan(start)) return {std::nullopt, HitStatus::Failed};
    if (start <= 0.0) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
    return first_hit_from_outside(h, span, counters);
}

HitResult SphereMethod::first_hit_from_outside(RayFunction& h, Span span, TraceCounters& counters) {
    const std::uint64_t nans = counters.nan_evaluations;
    const Crossing marched = tracer_.first_crossing(h, span, 1.0, counters);
    // Not outside at t0 after all (a pole crossed in an earlier octree cell
    // changes H's sign without a root): the march stops there at once, on
    // H(t0) ≤ 0, and the start is the hit, as first_hit has it.
    if (marched.t == span.t0 && marched.end == span.t0 && !marched.exact && counters.nan_evaluations == nans)
        return {span.t0, HitStatus::Ok};
    const Crossing hit = refined(h, marched, nans, counters);
    if (hit.t) return {hit.t, HitStatus::Ok};
    return {std::nullopt, hit.gave_up || counters.nan_evaluations != nans ? HitStatus::Failed : HitStatus::NoHit};
}

HitStatus SphereMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    const double start = h.value(span.t0, counters);
    if (std::isnan(start)) return HitStatus::Failed;
    const std::size_t before = hits.size();
    const std::uint64_t nans = counters.nan_evaluations;
    double side = start > 0.0 ? 1.0 : -1.0;
    double t = span.t0;
    bool gave_up = false;
    const double reach = 2.0 * tracer_.step_epsilon(h, far_end(span)), merge = h.to_t(merge_width_);
    const auto add = [&](double root) {
        hits.push_back(root);
        if (hits.size() - before <= max_hits_) return true;
        hits.pop_back();
        gave_up = true;
        return false;
    };
    while (t < span.t1) {
        const Crossing next = crossing(h, {t, span.t1}, side, counters);
        gave_up = next.gave_up;
        if (!next.t) break;
        double root = std::max(*next.t, t);
        if (!add(root)) break;
        // The march resumes 2ε past a root; roots closer than that (a chord
        // or a wall thinner than 2ε) are isolated by intervals, one by one.
        for (;;) {
            const Span close{root + merge, std::min(root + reach, span.t1)};
            if (!(close.t0 < close.t1)) break;
            const HitResult found = close_roots_.first_root_on_tape_in_use(h, close, counters);
            if (found.status == HitStatus::Failed) gave_up = true;
            if (!found.t || !add(*found.t)) break;
            root = *found.t;
        }
        if (gave_up) break;
        // Resume past the last root, on whichever side the ray is there.
        t = root + reach;
        if (t >= span.t1) break;
        const double past = h.value(t, counters);
        if (std::isnan(past)) break;
        side = past > 0.0 ? 1.0 : -1.0;
    }
    if (gave_up || counters.nan_evaluations != nans) return HitStatus::Failed;
    return hits.size() > before ? HitStatus::Ok : HitStatus::NoHit;
}

}  // namespace zeroset
