// Root refinement once a root is isolated: "once a root is isolated within a
// monotonic segment, a combination of Newton's method and regula falsi can
// quickly refine the root to machine precision" (survey §4, after Mitchell;
// the LG method of §5.1 ends the same way). This is that combination, as a
// safeguarded Newton iteration on a sign-change bracket:
//
//   - Newton (eq. 22) from the end of the bracket with the smaller |H| — or
//     regula falsi where H′ is not known there (an end given by its value
//     alone); its point is taken when it lies strictly inside the bracket,
//     otherwise the step bisects. The bracket always shrinks, by the side
//     of the surface (H ≤ 0 inside) that H takes at the new point.
//   - Newton converges from one side, so the far end would never move. A
//     Newton step shorter than half the x tolerance is lengthened to that,
//     and one too small to change t moves t to the next double: the point
//     lands just across the root and the bracket closes (to adjacent doubles
//     at full precision).
//   - At a root of multiplicity m (a grazing ray through an inflection, a
//     flat field) Newton is only linear: each step is (m − 1)/m of the one
//     before. When two successive steps show that ratio, the step is taken m
//     times, which lands on such a root at once.
//   - A step counts as progress when it halves the bracket, or when it is a
//     Newton step at most half as long as the Newton step before last (the
//     test of Numerical Recipes' rtsafe). After three steps without progress
//     it bisects, so a bracket that is not monotone after all, or a derivative
//     that misleads, costs a few bisections, no more.
//
// The result is a root to full double precision (adjacent doubles) unless a
// coarser x_tolerance is asked for.
#pragma once

#include <cmath>
#include <limits>

#include "zeroset/roots/bracket.hpp"
#include "zeroset/roots/root_function.hpp"

namespace zeroset {

namespace detail {
/// The Newton step from p, −H/H′ (eq. 22), or NaN when H′ is 0 or not finite.
inline double newton_step(const BracketPoint& p) {
    const double derivative = p.h.derivative;
    if (derivative == 0.0 || !std::isfinite(derivative)) return std::numeric_limits<double>::quiet_NaN();
    return -p.h.value / derivative;
}

/// The regula falsi step from p over the bracket [lo, hi] — for an end
/// whose H′ is not known (NaN) — or NaN when the ends' secant is flat or not
/// finite.
inline double secant_step(const BracketPoint& p, const BracketPoint& lo, const BracketPoint& hi) {
    const double slope = (hi.h.value - lo.h.value) / (hi.t - lo.t);
    if (slope == 0.0 || !std::isfinite(slope)) return std::numeric_limits<double>::quiet_NaN();
    return -p.h.value / slope;
}

/// Where refine_root evaluates next from `from`, given the Newton step there
/// and the Newton step before it.
inline double next_point(double from, double step, double previous_step, double min_step) {
    // At a root of multiplicity m Newton is linear, each step (m − 1)/m of
    // the one before: then take m steps at once (m ≥ 2; the threshold leaves
    // room for rounding at m = 2).
    const double ratio = step / previous_step;
    if (ratio > 0.45 && ratio < 1.0) step *= std::round(1.0 / (1.0 - ratio));
    // Land just past a root Newton has all but found, so the far end moves.
    if (std::abs(step) < min_step) step = std::copysign(min_step, step);
    const double next = from + step;
    return next != from ? next : std::nextafter(from, std::copysign(std::numeric_limits<double>::infinity(), step));
}

/// Safeguarded Newton on a bracket search already started (see refine_root).
template <class F>
BracketResult refine(F& h, BracketSearch& search, const BracketOptions& options) {
    double previous_step = std::numeric_limits<double>::quiet_NaN();  // the last Newton step taken
    double length_before_last = std::numeric_limits<double>::infinity();
    while (search.running(options)) {
        double t = search.midpoint();
        double step = std::numeric_limits<double>::quiet_NaN();  // stays NaN when this step bisects
        if (!search.must_bisect()) {
            const BracketPoint& from = search.best();
            step = std::isnan(from.h.derivative) ? detail::secant_step(from, search.lo(), search.hi())
                                                 : detail::newton_step(from);
            const double next = detail::next_point(from.t, step, previous_step, 0.5 * options.x_tolerance);
            if (search.strictly_inside(next)) {
                t = next;
            } else {
                step = std::numeric_limits<double>::quiet_NaN();
            }
        }
        search.step(h, t);
        if (!std::isnan(step)) {
            if (std::abs(step) <= 0.5 * length_before_last) search.note_progress();
            length_before_last = std::abs(previous_step);
            previous_step = step;
        }
    }
    return search.result(options);
}
}  // namespace detail

/// The root of h in [a, b], where h(a) and h(b) lie on opposite sides of the
/// surface (H ≤ 0 inside) or one of them is exactly 0 (a, the lower end, wins).
/// h returns H and H′ together. On a monotone segment the root is unique;
/// otherwise this finds one of them.
template <DifferentiableFunction F>
BracketResult refine_root(F&& h, double a, double b, const BracketOptions& options = {}) {
    BracketSearch search(h, a, b);
    return detail::refine(h, search, options);
}

/// The same from ends where H and H′ are already known (lo.t ≤ hi.t): no
/// evaluation is spent on them again.
template <DifferentiableFunction F>
BracketResult refine_root(F&& h, const BracketPoint& lo, const BracketPoint& hi, const BracketOptions& options = {}) {
    BracketSearch search(lo, hi);
    return detail::refine(h, search, options);
}

}  // namespace zeroset
