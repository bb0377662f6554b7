// First hit and all hits over an isolation walk.
#include "zeroset/trace/isolating_method.hpp"

#include <cmath>

namespace zeroset {

HitResult IsolatingMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    const double start = h.value(span.t0, counters);
    if (start != start) return {std::nullopt, HitStatus::Failed};
    if (start <= 0.0) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
    return first_hit_from_outside(h, span, counters);
}

HitResult IsolatingMethod::first_hit_from_outside(RayFunction& h, Span span, TraceCounters& counters) {
    std::optional<double> first;
    auto take_first = [&first](double t) {
        first = t;
        return false;
    };
    const std::uint64_t nans = counters.nan_evaluations;
    const HitStatus status = isolate(h, span, counters, take_first);
    h.use_full_tape();
    if (counters.nan_evaluations != nans) return {std::nullopt, HitStatus::Failed};  // H undefined on the way
    if (first) return {first, HitStatus::Ok};
    return {std::nullopt, status};
}

bool IsolatingMethod::split_undecided(const RayFunction& h, const Segment& s, const Jet<Interval>& e,
                                      const SegmentStack& segments) const {
    if (!segments.can_split(s)) return false;
    if (s.b - s.a > h.to_t(settings_.tangent_width)) return true;
    // A kink: H″ unbounded while H′ stays bounded (the hull of the branches'
    // slopes). Where H′ is unbounded too — a jump or a pole — splitting on
    // would not settle it; finest_segment_hit does.
    const auto unbounded = [](const Interval& x) { return x.is_empty() || !std::isfinite(x.magnitude()); };
    const bool kink = unbounded(e.d2) && !unbounded(e.d1);
    return kink && SegmentStack::above_resolution(s);
}

bool IsolatingMethod::narrow(RayFunction& h, const Segment& s, TraceCounters& counters) {
    if (!h.can_prune()) return true;
    const Interval f = h.prune(s.depth, s.a, s.b, counters);
    return f.is_empty() || f.contains(0.0);  // an empty f (NaN) is left to the method's own enclosure
}

HitStatus IsolatingMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    const std::size_t before = hits.size();
    const double merge_width = 4.0 * h.to_t(settings_.tangent_width);
    auto collect = [&](double t) {
        // A root on the boundary of two segments is found from both sides, and
        // a tangent root may span neighbouring finest segments: keep one.
        if (hits.size() == before || t - hits.back() > merge_width) hits.push_back(t);
        return hits.size() - before <= settings_.max_hits;  // one past the cap shows there are more
    };
    const std::uint64_t nans = counters.nan_evaluations;
    const HitStatus status = isolate(h, span, counters, collect);
    h.use_full_tape();
    if (status == HitStatus::Failed || counters.nan_evaluations != nans) return HitStatus::Failed;
    if (hits.size() - before > settings_.max_hits) {
        hits.pop_back();
        return HitStatus::Failed;
    }
    return hits.size() > before ? HitStatus::Ok : HitStatus::NoHit;
}

}  // namespace zeroset
