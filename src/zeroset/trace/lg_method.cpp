// Kalra–Barr LG isolation (Fig. 11) with Newton refinement.
#include "zeroset/trace/lg_method.hpp"

#include <cmath>

#include "zeroset/trace/refine_bracket.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {
/// max |x| over the interval; unbounded when the enclosure was lost (empty).
double bound_of(const Interval& x) { return x.is_empty() ? INFINITY : x.magnitude(); }
}  // namespace

HitStatus LgMethod::isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) {
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    while (!segments.empty()) {
        const Segment s = segments.pop();
        const double tm = 0.5 * (s.a + s.b), r = 0.5 * (s.b - s.a);  // Fig. 11, step 1
        const Jet<Interval> e = h.enclose(s.a, s.b, counters);
        if (settings_.log) settings_.log->interval_boxes.push_back({s.a, s.b, e.v.lo, e.v.hi});
        if (e.v.is_empty()) return HitStatus::Failed;  // H is undefined (NaN) over the segment
        // The enclosure of H comes with those of H′ and H″ at no extra cost, and
        // excludes roots even where L is unbounded (e.g. near a division by 0).
        if (!e.v.contains(0.0)) continue;
        const double lip_h = bound_of(e.d1);   // L = Lip H on the segment
        const double lip_dh = bound_of(e.d2);  // step 2: G = Lip H′ on the segment
        const Jet<double> at_mid = h.jet(tm, counters);
        if (std::isnan(at_mid.v) || std::isnan(at_mid.d1)) return HitStatus::Failed;
        if (std::abs(at_mid.v) > lip_h * r) continue;  // no root within L·r of t_m
        if (std::abs(at_mid.d1) > lip_dh * r) {        // step 3: H is monotone
            if (const auto root = refine_sign_change(h, s.a, s.b, counters))
                if (!visit(*root)) return HitStatus::Ok;  // 3a: a single root
            continue;                                     // 3b: none
        }
        if (r > 0.5 * settings_.tangent_width && segments.can_split(s)) {
            segments.split(s, s.a);  // step 4: divide and conquer, front half first
            continue;
        }
        if (!visit(s.a)) return HitStatus::Ok;  // still undecided at the finest width: a tangent root
    }
    return HitStatus::NoHit;
}

}  // namespace zeroset
