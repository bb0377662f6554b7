// Mitchell's interval root isolation (Fig. 9) with Newton refinement.
#include "zeroset/trace/interval_method.hpp"

#include "zeroset/trace/refine_bracket.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {

/// H over the segment by the mean-value form H(t_m) + H′[T]·(T − t_m): its
/// overestimate shrinks with the square of the width where the plain
/// enclosure's shrinks with the width, which is what rejects a ray passing
/// a hair above the surface without bisecting it into millions of pieces.
Interval mean_value_form(RayFunction& h, const Segment& s, const Interval& slope, TraceCounters& counters) {
    const double tm = 0.5 * (s.a + s.b);
    const Interval at_mid = h.enclose_value(tm, counters);
    return at_mid + slope * Interval(s.a - tm, s.b - tm);
}

}  // namespace

HitStatus IntervalMethod::isolate_segments(RayFunction& h, Span span, bool prune, TraceCounters& counters,
                                           RootVisitor visit) {
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    const std::uint64_t nans = counters.nan_evaluations;
    for (long visited = 0; !segments.empty(); ++visited) {
        if (visited == settings_.max_segments || counters.nan_evaluations != nans || counters.over_limit())
            return HitStatus::Failed;
        const Segment s = segments.pop();
        if (prune && !narrow(h, s, counters)) continue;  // and the tape pruned to s
        const Jet<Interval> e = h.enclose(s.a, s.b, counters);
        if (settings_.log) settings_.log->interval_boxes.push_back({s.a, s.b, e.v.lo, e.v.hi});
        if (e.v.is_empty()) return HitStatus::Failed;  // H is undefined (NaN) over the segment
        if (!e.v.contains(0.0)) continue;               // Fig. 9, step 2: no root here
        if (!e.d1.is_empty() && !e.d1.contains(0.0)) {  // step 4: H is monotone
            if (const auto root = refine_sign_change(h, s.a, s.b, counters))
                if (!visit(*root)) return HitStatus::Ok;
            continue;
        }
        if (!mean_value_form(h, s, e.d1, counters).contains(0.0)) continue;  // a near miss
        if (split_undecided(h, s, e, segments)) {
            segments.split(s, s.a);  // step 5: divide and conquer, front half first
            continue;
        }
        // Still ambiguous at the finest width: a tangent root, or a jump.
        if (const auto hit = finest_segment_hit(h, s.a, s.b, e, counters))
            if (!visit(*hit)) return HitStatus::Ok;
    }
    return HitStatus::NoHit;
}

HitResult IntervalMethod::first_root_on_tape_in_use(RayFunction& h, Span span, TraceCounters& counters) {
    std::optional<double> first;
    auto take_first = [&first](double t) {
        first = t;
        return false;
    };
    const HitStatus status = isolate_segments(h, span, false, counters, take_first);
    if (first) return {first, HitStatus::Ok};
    return {std::nullopt, status};
}

}  // namespace zeroset
