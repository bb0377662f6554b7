// IsolatingMethod: the methods that hand over their roots one by one, in
// increasing t — by subdividing the span (interval, LG) or by sampling it
// for brackets (regula falsi, bisection). first_hit and all_hits are the
// same walk over those roots.
#pragma once

#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/root_visitor.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

class IsolatingMethod : public RootFinder {
public:
    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) final;
    HitResult first_hit_from_outside(RayFunction& h, Span span, TraceCounters& counters) final;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) final;

protected:
    explicit IsolatingMethod(const RootFinderSettings& settings) : settings_(settings) {}

    /// Hands the roots in the span to `visit`, in increasing t, until it
    /// returns false. Returns Failed where the search broke down (H undefined,
    /// NaN, a budget spent), else NoHit.
    virtual HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) = 0;

    /// Whether a segment that may still hold a root is split again (else it
    /// is taken as a tangent root). Segments wider than the tangent width
    /// are split. A narrower one is split on, down to the resolution of
    /// doubles, where H″ is unbounded over it: there a min, max or abs
    /// switches branch (a kink, §7) rather than H touching 0 smoothly, and
    /// a ray passing a hair outside an edge must not count as a hit.
    [[nodiscard]] bool split_undecided(const RayFunction& h, const Segment& s, const Jet<Interval>& e,
                                       const SegmentStack& segments) const;

    /// Where the tape has a min or max, prunes it to the segment's box
    /// (RayFunction::prune), so the enclosures and refinement on the segment
    /// and its halves walk the shorter tape. False when f over the box
    /// certainly excludes 0: no root on the segment.
    static bool narrow(RayFunction& h, const Segment& s, TraceCounters& counters);

    RootFinderSettings settings_;
};

}  // namespace zeroset
