// Running one solver over a set of algebraic rays.
#include "support/algebraic_accuracy.hpp"

#include <algorithm>
#include <cmath>

#include "zeroset/trace/polynomial_method.hpp"

namespace zeroset::test {

double SolverAccuracy::max_error() const { return errors.empty() ? 0.0 : *std::ranges::max_element(errors); }

double SolverAccuracy::median_error() const {
    if (errors.empty()) return 0.0;
    std::vector<double> sorted = errors;
    std::ranges::sort(sorted);
    return sorted[sorted.size() / 2];
}

SolverAccuracy measure_solver(const Object& object, const std::vector<AlgebraicRay>& rays, PolynomialSolver solver,
                              double lengthen) {
    const Tape tape(object.surface);
    const double scale = object.bounds.enclosing_box().diagonal();
    RootFinderSettings settings = settings_for_scale(scale);
    settings.polynomial_solver = solver;
    PolynomialMethod method(tape, settings);
    MpfiRayOracle oracle(object.surface, scale);
    RayFunction h(tape);
    SolverAccuracy a;
    for (const AlgebraicRay& r : rays) {
        h.set_ray(r.ray);
        TraceCounters counters;
        const HitResult hit = method.first_hit(h, Span{r.span.t0, r.span.t1 + lengthen}, counters);
        ++a.rays;
        std::optional<OracleRoot> reference = r.reference;
        if (oracle.sign(r.ray, r.span.t0) < 0) reference = OracleRoot{r.span.t0, RootKind::Simple, 0.0};
        const double resolution = method.rounding_bound(r.ray, r.span);
        double tolerance = 1e-7 * scale;
        if (reference && reference->kind == RootKind::Simple && reference->slope > 0.0) {
            tolerance = std::max(1e-9 * scale, 2.0 * resolution / reference->slope);
        }
        if (reference && (!hit.t || *hit.t > reference->t + tolerance)) {
            ++a.misses;
            continue;
        }
        if (!hit.t) continue;
        if (reference && *hit.t >= reference->t - tolerance) {
            a.errors.push_back(std::abs(*hit.t - reference->t) / scale);
            continue;
        }
        ++a.unresolved_hits;
        a.worst_unresolved = std::max(a.worst_unresolved, oracle.magnitude(r.ray, *hit.t) / resolution);
    }
    return a;
}

}  // namespace zeroset::test
