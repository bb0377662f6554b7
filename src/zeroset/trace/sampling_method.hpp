// The bracketing methods of the survey's §2: regula falsi (with the
// Anderson–Björck fix) and bisection (Fig. 6). They need a sign-change
// bracket, found here by sampling the span at `bracket_samples` points — the
// ad hoc isolation the survey faults: two roots between neighbouring samples
// (a thin feature, a grazing ray) are missed. Not guaranteed.
#pragma once

#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/root_visitor.hpp"

namespace zeroset {

class SamplingMethod : public RootFinder {
public:
    enum class Refinement { RegulaFalsi, Bisection };

    SamplingMethod(Refinement refinement, const RootFinderSettings& settings)
        : refinement_(refinement), settings_(settings) {}

    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) override;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) override;

private:
    /// Hands the refined root of each sampled bracket to `visit`, in order,
    /// until it returns false.
    HitStatus visit_roots(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) const;
    /// The root in a sign-change bracket, refined by this method's rule.
    std::optional<double> refine(RayFunction& h, double a, double b, TraceCounters& counters) const;

    Refinement refinement_;
    RootFinderSettings settings_;
};

}  // namespace zeroset
