// Newton's method as a ray-intersection method (survey §2, eq. 22, Fig. 4):
// iterate from a start (the span's t0 unless given) and report the root it
// converges to — which need not be the first one — or that it diverged (left
// the span widened by its length on each side) or failed (zero derivative,
// iteration limit, NaN). A root it reaches outside the span is no hit. It
// guarantees nothing; it is here to show why root isolation matters.
#pragma once

#include "zeroset/trace/root_finder.hpp"

namespace zeroset {

class NewtonMethod : public RootFinder {
public:
    explicit NewtonMethod(const RootFinderSettings& settings) : settings_(settings) {}

    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) override;
    /// The one root Newton reaches, if any.
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) override;

private:
    RootFinderSettings settings_;
};

}  // namespace zeroset
