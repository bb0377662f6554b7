// The bracketing methods of the survey's §2: regula falsi (with the
// Anderson–Björck fix) and bisection (Fig. 6). They need a sign-change
// bracket, found here by sampling the span at `bracket_samples` points — the
// ad hoc isolation the survey faults: two roots between neighbouring samples
// (a thin feature, a grazing ray) are missed. Not guaranteed.
#pragma once

#include "zeroset/trace/isolating_method.hpp"

namespace zeroset {

class SamplingMethod : public IsolatingMethod {
public:
    enum class Refinement { RegulaFalsi, Bisection };

    SamplingMethod(Refinement refinement, const RootFinderSettings& settings)
        : IsolatingMethod(settings), refinement_(refinement) {}

protected:
    /// Hands the refined root of each sampled bracket to `visit`, in order.
    HitStatus isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) override;

private:
    /// What refining a sign-change bracket found.
    struct Refined {
        enum { Root, Pole, Failed } kind;
        double t;
    };
    /// The root in a sign-change bracket, refined by this method's rule — or
    /// a pole there, or a failure to converge.
    Refined refine(RayFunction& h, double a, double b, TraceCounters& counters) const;

    Refinement refinement_;
};

}  // namespace zeroset
