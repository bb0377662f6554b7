// Running one solver over a set of algebraic rays.
#include "support/algebraic_accuracy.hpp"

#include <algorithm>
#include <cmath>

#include "zeroset/trace/root_finder.hpp"

namespace zeroset::test {

double SolverAccuracy::max_error() const { return errors.empty() ? 0.0 : *std::ranges::max_element(errors); }

double SolverAccuracy::median_error() const {
    if (errors.empty()) return 0.0;
    std::vector<double> sorted = errors;
    std::ranges::sort(sorted);
    return sorted[sorted.size() / 2];
}

SolverAccuracy measure_solver(const Object& object, const std::vector<AlgebraicRay>& rays, PolynomialSolver solver) {
    const Tape tape(object.surface);
    const double scale = object.bounds.enclosing_box().diagonal();
    RootFinderSettings settings = settings_for_scale(scale);
    settings.polynomial_solver = solver;
    const auto finder = make_root_finder(Method::Polynomial, tape, settings);
    RayFunction h(tape);
    SolverAccuracy a;
    for (const AlgebraicRay& r : rays) {
        h.set_ray(r.ray);
        TraceCounters counters;
        const HitResult hit = finder->first_hit(h, r.span, counters);
        ++a.rays;
        if (!r.reference) {
            if (hit.t) ++a.false_hits;
            continue;
        }
        const bool well_conditioned = r.reference->kind == RootKind::Simple && r.reference->slope >= 1e-6;
        const double tolerance = (well_conditioned ? 1e-9 : 1e-7) * scale;
        if (!hit.t || *hit.t > r.reference->t + tolerance) {
            ++a.misses;
            continue;
        }
        a.errors.push_back(std::abs(*hit.t - r.reference->t) / scale);
    }
    return a;
}

}  // namespace zeroset::test
