// Sampled brackets refined by regula falsi or bisection (roots/).
#include "zeroset/trace/sampling_method.hpp"

#include <cmath>

#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/regula_falsi.hpp"
#include "zeroset/roots/sign_change_brackets.hpp"

namespace zeroset {

std::optional<double> SamplingMethod::refine(RayFunction& h, double a, double b, TraceCounters& counters) const {
    auto value = [&](double t) { return h.value(t, counters); };
    const BracketResult r = refinement_ == Refinement::RegulaFalsi ? regula_falsi(value, a, b) : bisection(value, a, b);
    if (r.status != BracketStatus::Converged) return std::nullopt;
    return r.t;
}

HitStatus SamplingMethod::isolate(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) {
    bool failed = false;
    bool stopped = false;
    auto value = [&](double t) { return h.value(t, counters); };
    for_each_sign_change(value, span.t0, span.t1, settings_.bracket_samples, [&](const Bracket& bracket) {
        const auto root = refine(h, bracket.lo, bracket.hi, counters);
        if (!root) {
            failed = true;
            return true;
        }
        stopped = !visit(*root);
        return !stopped;
    });
    return failed && !stopped ? HitStatus::Failed : HitStatus::NoHit;
}

}  // namespace zeroset
