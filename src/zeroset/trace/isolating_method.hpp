// IsolatingMethod: the methods that isolate roots by subdividing the span
// (interval, LG). They differ only in how a segment is settled; first_hit and
// all_hits are the same walk over the isolated roots.
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
    /// returns false. Returns Failed where H is undefined (NaN), else NoHit.
    virtual HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) = 0;

    RootFinderSettings settings_;
};

}  // namespace zeroset
