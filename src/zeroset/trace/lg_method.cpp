// Kalra–Barr LG isolation (Fig. 11) with Newton refinement.
#include "zeroset/trace/lg_method.hpp"

#include <cmath>

#include "zeroset/trace/refine_bracket.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {
/// max |x| over the interval; unbounded when the enclosure was lost (empty).
double bound_of(const Interval& x) { return x.is_empty() ? INFINITY : x.magnitude(); }
/// min |x| over the interval (0 when it holds 0 or is empty).
double least_of(const Interval& x) {
    if (x.is_empty() || x.contains(0.0)) return 0.0;
    return std::min(std::abs(x.lo), std::abs(x.hi));
}
}  // namespace

HitStatus LgMethod::isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) {
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    const std::uint64_t nans = counters.nan_evaluations;
    for (long visited = 0; !segments.empty(); ++visited) {
        if (visited == settings_.max_segments || counters.nan_evaluations != nans || counters.over_limit())
            return HitStatus::Failed;
        const Segment s = segments.pop();
        if (!narrow(h, s, counters)) continue;  // and the tape pruned to s
        const double tm = 0.5 * (s.a + s.b);                      // Fig. 11, step 1
        const double r = std::max(tm - s.a, s.b - tm);             // exact half-width bound
        const Jet<Interval> e = h.enclose(s.a, s.b, counters);
        if (settings_.log) settings_.log->interval_boxes.push_back({s.a, s.b, e.v.lo, e.v.hi});
        if (e.v.is_empty()) return HitStatus::Failed;  // H is undefined (NaN) over the segment
        // The enclosure of H comes with those of H′ and H″ at no extra cost, and
        // excludes roots even where L is unbounded (e.g. near a division by 0).
        if (!e.v.contains(0.0)) continue;
        const double lip_h = bound_of(e.d1);   // L = Lip H on the segment
        const double lip_dh = bound_of(e.d2);  // step 2: G = Lip H′ on the segment
        // H(t_m) and H′(t_m) as enclosures too, so rounding in them can never
        // make the tests below claim more than is true.
        const Jet<Interval> at_mid = h.enclose(tm, tm, counters);
        if (at_mid.v.is_empty()) return HitStatus::Failed;
        if (least_of(at_mid.v) > lip_h * r) continue;  // no root within L·r of t_m
        // Step 3: H is monotone. Where G is unbounded (a kink of min, max or
        // abs inside the segment) the enclosure of H′ may still show it.
        const bool monotone = least_of(at_mid.d1) > lip_dh * r ||
                              (!std::isfinite(lip_dh) && !e.d1.is_empty() && !e.d1.contains(0.0));
        if (monotone) {
            if (const auto root = refine_sign_change(h, s.a, s.b, counters))
                if (!visit(*root)) return HitStatus::Ok;  // 3a: a single root
            continue;                                     // 3b: none
        }
        if (split_undecided(h, s, e, segments)) {
            segments.split(s, s.a);  // step 4: divide and conquer, front half first
            continue;
        }
        // Still undecided at the finest width: a tangent root, or a jump.
        if (const auto hit = finest_segment_hit(h, s.a, s.b, e, counters))
            if (!visit(*hit)) return HitStatus::Ok;
    }
    return HitStatus::NoHit;
}

}  // namespace zeroset
