// The LG method (Kalra and Barr 1989; survey §5.1, Fig. 11). On a segment
// with midpoint t_m and half-width r, with L = Lip H and G = Lip H′ there:
// |H(t_m)| > L·r proves there is no root; |H′(t_m)| > G·r proves H monotone,
// and then a sign change at the ends proves exactly one root, refined by
// guarded Newton. Otherwise the segment is halved. L and G come from the
// interval enclosures of H′ and H″ over the segment (Jet<Interval>), so no
// constant is ever supplied by hand; the enclosure of H, which comes with
// them, also drops segments where it excludes 0. Where G is unbounded — a
// min, max or abs switching branch inside the segment — the enclosure of H′
// may still prove H monotone. Segments still undecided at `tangent_width`
// are reported as tangent hits, kinks resolved to the resolution of doubles
// first, as in the interval method.
#pragma once

#include "zeroset/trace/isolating_method.hpp"

namespace zeroset {

class LgMethod : public IsolatingMethod {
public:
    explicit LgMethod(const RootFinderSettings& settings) : IsolatingMethod(settings) {}

protected:
    HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) override;
};

}  // namespace zeroset
