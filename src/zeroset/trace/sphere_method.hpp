// Sphere tracing (survey §5.2, Fig. 12; see sphere_tracer.hpp) behind the
// RootFinder interface, with a final refinement so its hits are as precise
// as the other methods'. All hits alternate between entering the solid
// (tracing f) and leaving it (tracing −f); after each root, the 2ε the
// march cannot resolve are searched by interval isolation, so a wall or
// chord thinner than that keeps both its roots, as with the interval method.
#pragma once

#include <cstdint>

#include "zeroset/trace/interval_method.hpp"
#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/sphere_tracer.hpp"

namespace zeroset {

class SphereMethod : public RootFinder {
public:
    explicit SphereMethod(const RootFinderSettings& settings);

    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) override;
    HitResult first_hit_from_outside(RayFunction& h, Span span, TraceCounters& counters) override;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) override;

private:
    /// The first crossing in the span (entering the solid when side = 1,
    /// leaving it when −1), refined; nothing after a NaN.
    Crossing crossing(RayFunction& h, Span span, double side, TraceCounters& counters);
    /// The march's crossing refined to full precision (`nans`: the NaN count before the march).
    static Crossing refined(RayFunction& h, const Crossing& marched, std::uint64_t nans, TraceCounters& counters);

    SphereTracer tracer_;
    IntervalMethod close_roots_;  // for all hits: roots within 2ε of the last one
    double merge_width_;          // in space: roots closer than this are one (as IsolatingMethod::all_hits)
    std::size_t max_hits_;
};

}  // namespace zeroset
