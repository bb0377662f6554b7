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

HitStatus SamplingMethod::visit_roots(RayFunction& h, Span span, TraceCounters& counters, RootVisitor visit) const {
    bool failed = false;
    bool found = false;
    auto value = [&](double t) { return h.value(t, counters); };
    for_each_sign_change(value, span.t0, span.t1, settings_.bracket_samples, [&](const Bracket& bracket) {
        const auto root = refine(h, bracket.lo, bracket.hi, counters);
        if (!root) {
            failed = true;
            return true;
        }
        found = true;
        return visit(*root);
    });
    if (found) return HitStatus::Ok;
    return failed ? HitStatus::Failed : HitStatus::NoHit;
}

HitResult SamplingMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    const double start = h.value(span.t0, counters);
    if (std::isnan(start)) return {std::nullopt, HitStatus::Failed};
    if (start <= 0.0) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
    std::optional<double> first;
    auto take_first = [&first](double t) {
        first = t;
        return false;
    };
    const HitStatus status = visit_roots(h, span, counters, take_first);
    return {first, status};
}

HitStatus SamplingMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    auto collect = [&hits](double t) {
        hits.push_back(t);
        return true;
    };
    return visit_roots(h, span, counters, collect);
}

}  // namespace zeroset
