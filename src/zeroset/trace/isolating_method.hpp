// IsolatingMethod: the methods that hand over their roots one by one, in
// increasing t — by subdividing the span (interval, LG) or by sampling it
// for brackets (regula falsi, bisection). first_hit and all_hits are the
// same walk over those roots.
#pragma once

#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/root_visitor.hpp"

namespace zeroset {

class IsolatingMethod : public RootFinder {
public:
    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) final;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) final;

protected:
    explicit IsolatingMethod(const RootFinderSettings& settings) : settings_(settings) {}

    /// Hands the roots in the span to `visit`, in increasing t, until it
    /// returns false. Returns Failed where the search broke down (H undefined,
    /// NaN, a budget spent), else NoHit.
    virtual HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) = 0;

    RootFinderSettings settings_;
};

}  // namespace zeroset
