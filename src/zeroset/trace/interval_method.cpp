// Mitchell's interval root isolation (Fig. 9) with Newton refinement.
#include "zeroset/trace/interval_method.hpp"

#include "zeroset/trace/refine_bracket.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

HitStatus IntervalMethod::isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) {
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    while (!segments.empty()) {
        const Segment s = segments.pop();
        const Jet<Interval> e = h.enclose(s.a, s.b, counters);
        if (settings_.log) settings_.log->interval_boxes.push_back({s.a, s.b, e.v.lo, e.v.hi});
        if (e.v.is_empty()) return HitStatus::Failed;  // H is undefined (NaN) over the segment
        if (!e.v.contains(0.0)) continue;               // Fig. 9, step 2: no root here
        if (!e.d1.is_empty() && !e.d1.contains(0.0)) {  // step 4: H is monotone
            if (const auto root = refine_sign_change(h, s.a, s.b, counters))
                if (!visit(*root)) return HitStatus::Ok;
            continue;
        }
        if (s.b - s.a > settings_.tangent_width && segments.can_split(s)) {
            segments.split(s, s.a);  // step 5: divide and conquer, front half first
            continue;
        }
        if (!visit(s.a)) return HitStatus::Ok;  // still ambiguous at the finest width: a tangent root
    }
    return HitStatus::NoHit;
}

}  // namespace zeroset
