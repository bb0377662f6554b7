// The interval method (Mitchell 1990; survey §4, Figs. 9 and 10). Bisect the
// span; drop a segment where the enclosure of H excludes 0; a segment where
// the enclosure of H′ excludes 0 is monotone and holds at most one root, which
// a sign change at its ends proves and guarded Newton refines to full double
// precision. A segment that still may hold a root at `tangent_width` is a
// tangent (double) root, or a feature too thin to tell apart: it is reported
// as a hit at its left end — unless a min, max or abs switches branch inside
// it (a CSG edge, §7): that is resolved on to the resolution of doubles, so a
// ray passing just outside an edge is not taken for a hit.
#pragma once

#include "zeroset/trace/isolating_method.hpp"

namespace zeroset {

class IntervalMethod : public IsolatingMethod {
public:
    explicit IntervalMethod(const RootFinderSettings& settings) : IsolatingMethod(settings) {}

    /// The first root of H in the span by the same isolation, walking the
    /// tape h has in use now without pruning it: for a caller that holds a
    /// tape pruned to a box around the span already — sphere tracing's
    /// ε-segments (sphere_tracer.hpp). Ok with the root (or a tangent hit at
    /// the tangent width), NoHit, or Failed (NaN, a budget spent).
    HitResult first_root_on_tape_in_use(RayFunction& h, Span span, TraceCounters& counters);

protected:
    HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) override {
        return isolate_segments(h, span, true, counters, visit);
    }

private:
    /// Fig. 9 over the span; each segment's tape pruned to it when `prune`.
    HitStatus isolate_segments(RayFunction& h, Span span, bool prune, TraceCounters& counters, RootVisitor visit);
};

}  // namespace zeroset
