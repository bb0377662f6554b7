// Sampled brackets refined by regula falsi or bisection (roots/).
#include "zeroset/trace/sampling_method.hpp"

#include <cmath>

#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/regula_falsi.hpp"
#include "zeroset/roots/sign_change_brackets.hpp"

namespace zeroset {

SamplingMethod::Refined SamplingMethod::refine(RayFunction& h, double a, double b, TraceCounters& counters) const {
    auto value = [&](double t) { return h.value(t, counters); };
    const BracketResult r = refinement_ == Refinement::RegulaFalsi ? regula_falsi(value, a, b) : bisection(value, a, b);
    if (r.status != BracketStatus::Converged) return {Refined::Failed, r.t};
    // A continuous H is finite at the bracket's ends and smaller at its root;
    // a sign change that closes in on ever larger values is a pole, not a root.
    const double at_a = std::abs(value(a)), at_b = std::abs(value(b));
    if (!std::isfinite(at_a) || !std::isfinite(at_b) || !(std::abs(value(r.t)) <= std::max(at_a, at_b)))
        return {Refined::Pole, r.t};
    return {Refined::Root, r.t};
}

HitStatus SamplingMethod::isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) {
    bool failed = false;
    bool stopped = false;
    auto value = [&](double t) { return h.value(t, counters); };
    for_each_sign_change(value, span.t0, span.t1, settings_.bracket_samples, [&](const Bracket& bracket) {
        const Refined root = refine(h, bracket.lo, bracket.hi, counters);
        if (root.kind == Refined::Pole) return true;  // a sign change, but no root
        if (root.kind == Refined::Failed) {
            failed = true;
            return true;
        }
        stopped = !visit(root.t);
        return !stopped;
    });
    return failed && !stopped ? HitStatus::Failed : HitStatus::NoHit;
}

}  // namespace zeroset
