// F(t) with its rounding bound, about the ray's point nearest f's origin and
// cut to its root radius there; then the chosen solver, guarded.
#include "zeroset/trace/polynomial_method.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "zeroset/roots/closed_form.hpp"
#include "zeroset/roots/descartes.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/laguerre.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"
#include "zeroset/roots/sturm.hpp"
#include "zeroset/roots/subdivided_first_root.hpp"

namespace zeroset {

namespace {

RayPolynomialProgram compiled(const Tape& tape) {
    RayPolynomialProgram::Compiled c = RayPolynomialProgram::compile(tape);
    if (!c.program) {
        throw std::invalid_argument("the polynomial method needs a surface that is a polynomial in x, y, z of degree at most " +
                                    std::to_string(RayPolynomialProgram::max_degree));
    }
    return std::move(*c.program);
}

/// The span in the centred parameter s = t − t_c.
struct CentredSpan {
    double t_c;
    double s0;
    double s1;
};

/// About the ray's focus when it lies in the span; else about the span's
/// point nearest the origin of f's coordinates.
CentredSpan centre(Span span, double focus, const Ray& ray) {
    if (!(focus >= span.t0 && focus <= span.t1)) {
        // (With d scaled to its largest component: |d|² neither overflows
        // nor underflows.)
        const double m = max_abs(ray.dir);
        const Vec3d d = ray.dir / m;
        const double nearest = -dot(ray.origin, d) / (dot(d, d) * m);
        focus = std::isfinite(nearest) ? std::clamp(nearest, span.t0, span.t1) : 0.5 * span.t0 + 0.5 * span.t1;
    }
    return {focus, std::min(span.t0 - focus, 0.0), std::max(span.t1 - focus, 0.0)};
}

/// Cuts the span to F's root radius about its centre: no root of F lies
/// beyond. About the point nearest the origin (or the focus) the radius is
/// about the surface's size, so the long span of an unbounded surface
/// shrinks to where the surface can be — and the guard, which takes F̂'s
/// bound at a piece's far end for the whole piece, does not blur the surface
/// with the bound from 10⁴ units away. Only a radius below an eighth of
/// the span's reach from the centre is looked for: most spans are about as
/// long as their surface, and a small trim would cost more than it saves.
/// The span keeps s0 ≤ 0 ≤ s1.
void cut_to_root_radius(const PolynomialEnclosure& f, CentredSpan& c) {
    const double within = std::max(-c.s0, c.s1);
    const double reach = root_radius(f, within, 0.125 * within);
    c.s0 = std::max(c.s0, -reach);
    c.s1 = std::min(c.s1, reach);
}

/// False, with the NaN recorded in h like every method records it, when a
/// coefficient of F̂ is not finite: f is NaN (0/0 folded into a constant) or
/// overflows along the ray, and no root of it means anything.
bool defined_along(RayFunction& h, std::span<const double> f, const CentredSpan& c, TraceCounters& counters) {
    for (const double coefficient : f) {
        if (!std::isfinite(coefficient)) {
            h.note_nan(h.ray().at(c.t_c), counters);
            return false;
        }
    }
    return true;
}

}  // namespace

PolynomialMethod::PolynomialMethod(const Tape& tape, const RootFinderSettings& settings)
    : settings_(settings), program_(compiled(tape)) {}

// Inlined into its callers: returned through memory, its spans were read
// back in wider loads than they were written with, which stalls.
[[gnu::always_inline]] inline PolynomialEnclosure PolynomialMethod::current_enclosure() {
    const std::span<const double> value = program_.value();
    for (std::size_t i = 0; i < value.size(); ++i) radius_[i] = program_.radius(static_cast<int>(i));
    return {value, std::span<const double>(radius_.data(), value.size())};
}

int PolynomialMethod::solve(std::span<const double> c, double t0, double t1, std::span<double> out,
                            TraceCounters& counters) const {
    PolynomialSolver solver = settings_.polynomial_solver;
    if (solver == PolynomialSolver::Closed && checked_degree(c, t0, t1) > max_closed_form_degree) solver = PolynomialSolver::Sturm;
    PolynomialRoots r;
    switch (solver) {
        case PolynomialSolver::Closed: {
            std::array<double, max_closed_form_degree> roots{};
            r.count = closed_form_roots_in(c, t0, t1, roots);
            r.evaluations = 1;
            for (int i = 0; i < r.count && i < static_cast<int>(out.size()); ++i) out[static_cast<std::size_t>(i)] = roots[static_cast<std::size_t>(i)];
            r.count = std::min(r.count, static_cast<int>(out.size()));
            break;
        }
        case PolynomialSolver::Sturm: r = sturm_roots(c, t0, t1, out); break;
        case PolynomialSolver::Descartes: r = descartes_roots(c, t0, t1, out); break;
        case PolynomialSolver::Laguerre: r = laguerre_roots(c, t0, t1, out); break;
        case PolynomialSolver::Fast: r = fast_polynomial_roots(c, t0, t1, out); break;
    }
    counters.point_evaluations += static_cast<std::uint64_t>(r.evaluations);
    return r.count;
}

HitResult PolynomialMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    ++counters.point_evaluations;  // one run of the compiled program
    CentredSpan c = centre(span, h.focus(), h.ray());
    program_.evaluate(h.ray(), c.t_c);
    const std::span<const double> value = program_.value();
    if (!defined_along(h, value, c, counters)) return {std::nullopt, HitStatus::Failed};
    const double start = horner(value, c.s0).value;
    if (start <= 0.0) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
    const auto hit_at = [&](double s) { return HitResult{std::clamp(c.t_c + s, span.t0, span.t1), HitStatus::Ok}; };

    std::array<double, 1> first{};
    const auto solve_first = [&](double s1) -> std::optional<double> {
        if (solve(value, c.s0, s1, first, counters) == 0) return std::nullopt;
        return first[0];
    };
    if (!program_.error_known()) {  // no bound to guard with: trust F̂
        const auto s = solve_first(c.s1);
        return s ? hit_at(*s) : HitResult{std::nullopt, HitStatus::NoHit};
    }

    const PolynomialEnclosure enclosure = current_enclosure();
    const double uncut_start = c.s0;
    cut_to_root_radius(enclosure, c);
    if (c.s0 > uncut_start) {
        // F has no root between the ray's start and the cut's, so the same
        // sign at both; where F̂ cannot show it at the cut, the start is kept.
        const double at_cut = horner(value, c.s0).value;
        const double bound = enclosure_bound(enclosure, c.s0);
        if (at_cut < -bound) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
        if (!(at_cut > bound)) c.s0 = uncut_start;
    }
    const auto answer = [&](const PossibleRoot& hit) {
        counters.point_evaluations += static_cast<std::uint64_t>(hit.evaluations);
        return hit.found ? hit_at(hit.t) : HitResult{std::nullopt, HitStatus::NoHit};
    };
    // The default solver: Bernstein subdivision settles misses and simple
    // crossings, and scans what it leaves undecided over the fast solver's
    // extrema (subdivided_first_root.hpp).
    if (settings_.polynomial_solver == PolynomialSolver::Fast)
        return answer(first_possible_root_subdividing(enclosure, c.s0, c.s1, settings_.tangent_width / length(h.ray().dir)));

    // Any other solver: most spans hold no root (rays that pass the surface
    // by within its bounds), which the Bernstein test settles at once. Else
    // the solver's first root, then F̂'s extrema before it as the roots of
    // F̂′. A root where F̂ is plainly not 0 (a cluster's midpoint, an
    // inaccurate closed form) is not trusted: the extrema then cover the
    // whole span, and the scan finds the root.
    if (provably_positive(enclosure, c.s0, c.s1)) return {std::nullopt, HitStatus::NoHit};
    std::optional<double> root = solve_first(c.s1);
    if (root && std::abs(horner(value, *root).value) > enclosure_bound(enclosure, *root)) root.reset();
    std::array<double, RayPolynomialProgram::max_degree> extrema{};
    const int extremum_count = extrema_of(value, c.s0, root.value_or(c.s1), extrema, counters);
    return answer(first_possible_root(enclosure, c.s0, root.value_or(c.s1),
                                      std::span<const double>(extrema.data(), static_cast<std::size_t>(extremum_count)),
                                      root.has_value()));
}

double PolynomialMethod::rounding_bound(const Ray& ray, Span span) {
    if (!program_.error_known()) return std::numeric_limits<double>::infinity();
    const CentredSpan c = centre(span, std::numeric_limits<double>::quiet_NaN(), ray);
    program_.evaluate(ray, c.t_c);
    const PolynomialEnclosure f = current_enclosure();
    return std::max(enclosure_bound(f, c.s0), enclosure_bound(f, c.s1));
}

HitStatus PolynomialMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    ++counters.point_evaluations;
    CentredSpan c = centre(span, h.focus(), h.ray());
    program_.evaluate(h.ray(), c.t_c);
    const std::span<const double> value = program_.value();
    if (!defined_along(h, value, c, counters)) return HitStatus::Failed;
    std::array<double, RayPolynomialProgram::max_degree> roots{};
    int count = 0;
    if (!program_.error_known()) {  // no bound to guard with: F̂'s roots
        count = solve(value, c.s0, c.s1, roots, counters);
    } else {
        // Guarded as the first hit is: F̂'s roots, and its extrema that come
        // within the rounding bound of 0 — so that spans built from these
        // hits (Roth CSG) miss no graze either.
        const PolynomialEnclosure enclosure = current_enclosure();
        cut_to_root_radius(enclosure, c);
        if (provably_positive(enclosure, c.s0, c.s1)) return HitStatus::NoHit;
        std::array<double, RayPolynomialProgram::max_degree> extrema{};
        const int extremum_count = extrema_of(value, c.s0, c.s1, extrema, counters);
        int evaluations = 0;
        count = possible_roots(enclosure, c.s0, c.s1,
                               std::span<const double>(extrema.data(), static_cast<std::size_t>(extremum_count)), roots,
                               evaluations);
        counters.point_evaluations += static_cast<std::uint64_t>(evaluations);
    }
    for (int i = 0; i < count; ++i) hits.push_back(std::clamp(c.t_c + roots[static_cast<std::size_t>(i)], span.t0, span.t1));
    return count > 0 ? HitStatus::Ok : HitStatus::NoHit;
}

int PolynomialMethod::extrema_of(std::span<const double> value, double s0, double s1, std::span<double> out,
                                 TraceCounters& counters) const {
    if (settings_.polynomial_solver == PolynomialSolver::Fast) {
        const PolynomialRoots e = fast_polynomial_extrema(value, s0, s1, out);
        counters.point_evaluations += static_cast<std::uint64_t>(e.evaluations);
        return e.count;
    }
    std::array<double, RayPolynomialProgram::max_degree> derivative{};
    for (std::size_t i = 1; i < value.size(); ++i) derivative[i - 1] = static_cast<double>(i) * value[i];
    return solve(std::span<const double>(derivative.data(), value.size() - 1), s0, s1, out, counters);
}

}  // namespace zeroset
