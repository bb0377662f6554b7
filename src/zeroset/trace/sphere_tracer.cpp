// Sphere tracing with per-segment Lipschitz bounds and pruned tapes (see
// sphere_tracer.hpp).
#include "zeroset/trace/sphere_tracer.hpp"

#include <cmath>
#include <limits>

#include "zeroset/trace/interval_method.hpp"
#include "zeroset/trace/refine_bracket.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {
// Secant probes a segment may make (each costs a point value, and a slope
// enclosure when it finds a sign change): enough for a ray closing in on a
// surface, few enough that a ray grazing one wastes little.
constexpr int max_probes = 3;

/// The first root of H in a bracket [lo, hi] of at most 2ε where side·H > 0
/// at lo and ≤ 0 at hi. The bracket holds an odd number of roots: a sheet
/// thinner than 2ε in front of the crossing adds two, and guarded Newton
/// lands on any of them. An enclosure of (side·H)′ over the bracket — the
/// marched segment's (`known_slope`), or one of its own — usually shows
/// side·H strictly falling: one root, which Newton refines. Where it does
/// not (the kinks of a distance's max(d, 0) lie on its surface, and their
/// enclosures cancel only in exact arithmetic), Newton's root r is the first
/// if steps of side·H / L from lo — L the bracket's bound on how fast side·H
/// falls — reach within the tangent width of r, f > 0 at each: nothing
/// before r is thicker than that, the interval method's own resolution.
/// Where a step finds f ≤ 0, or 64 steps do not get there, `isolate` (the
/// interval method, front first) settles the bracket from the last step on;
/// should it find nothing where the signs at the ends differ (they and the
/// enclosures disagree by rounding), Newton's root stands. Nothing when no
/// root lies in the bracket (it was cut at the span's end). The steps' L is
/// always from an enclosure over the bracket itself.
template <class Isolate>
Crossing first_root_of_bracket(RayFunction& h, Span bracket, double side, const Interval& known_slope,
                               double tangent_width, Isolate&& isolate, TraceCounters& counters) {
    constexpr int max_steps = 64;
    const auto [lo, hi] = bracket;
    const std::optional<double> root = lo < hi ? refine_sign_change(h, lo, hi, counters) : std::nullopt;
    const Crossing newton = root ? Crossing{root, false, *root, true} : Crossing{};
    const auto isolated = [&](double from, double to) { return isolate(from, to).value_or(newton); };
    if (!root) return isolated(lo, hi);
    if (known_slope.hi < 0.0) return newton;
    const Interval d1 = h.slope(lo, hi, counters);  // 0 where H is undefined: then the isolation fails
    const Interval slope = side > 0.0 ? d1 : -d1;
    if (slope.hi < 0.0) return newton;
    const double descent = -slope.lo;
    double t = lo, f = side * h.value(lo, counters);
    for (int steps = 0; steps < max_steps && f > 0.0 && std::isfinite(descent) && descent > 0.0; ++steps) {
        const double next = t + f / descent;
        if (next >= *root - tangent_width) return newton;
        const double f_next = side * h.value(next, counters);
        if (!(f_next > 0.0)) return isolated(t, hi);  // a root before Newton's (or a NaN): front first
        t = next, f = f_next;
    }
    return isolated(t, hi);
}

}  // namespace

double SphereTracer::step_epsilon(const RayFunction& h, double t) const {
    const double ulp = std::abs(std::nextafter(t, std::numeric_limits<double>::infinity()) - t);
    return std::max(h.to_t(settings_.epsilon), 4.0 * ulp);
}

Crossing SphereTracer::march(RayFunction& h, Span span, double side_at_start, TraceCounters& counters) const {
    // The march looks for where side·H falls to 0; past a pole H changes
    // sign without a root, and the side flips with it.
    double side = side_at_start;
    const auto value_at = [&](double t) { return side * h.value(t, counters); };
    // An enclosure of (side·H)′ over [from, to].
    const auto side_slope = [&](double from, double to) {
        const Interval slope = h.slope(from, to, counters);
        return side > 0.0 ? slope : -slope;
    };
    // The last point marched to where f > 0: the ray is clear up to it.
    double clear_to = span.t0;
    // An ε-segment [from, to] which steps cannot settle, or a bracket: its
    // first root by Mitchell's isolation down to the tangent width, on the
    // tape in use (the segment's, whose box reaches 2ε past its end, or the
    // full one). Nothing when it holds none before t1 (a root past t1 is not
    // the span's).
    const auto first_root_in = [&](double from, double to) -> std::optional<Crossing> {
        to = std::min(to, span.t1);
        if (!(from < to)) return std::nullopt;
        const std::uint64_t nans = counters.nan_evaluations;
        RootFinderSettings isolating;
        isolating.tangent_width = settings_.tangent_width;
        isolating.max_segments = settings_.max_segments;
        IntervalMethod isolation(isolating);
        const HitResult root = isolation.first_root_on_tape_in_use(h, {from, to}, counters);
        if (counters.nan_evaluations != nans) return Crossing{};
        if (root.status == HitStatus::Failed) return Crossing{std::nullopt, true};
        if (root.t) return Crossing{root.t, false, *root.t, true};
        return std::nullopt;
    };
    // The segment being marched and the enclosure of H′ over it.
    double segment_a = span.t0, segment_b = span.t0;
    Interval segment_slope = Interval::entire();
    // A bracket with a sign change, at most 2ε: its first root (see first_root_of_bracket).
    const auto settle = [&](double lo, double hi) -> Crossing {
        const bool in_segment = lo >= segment_a && hi <= segment_b;
        const Interval known = !in_segment ? Interval::entire() : side > 0.0 ? segment_slope : -segment_slope;
        return first_root_of_bracket(h, {lo, std::min(hi, span.t1)}, side, known, h.to_t(settings_.tangent_width),
                                     first_root_in, counters);
    };
    // f ≤ 0 at t, reached by a step or as a segment's start: the crossing is
    // in (clear_to, t]. A step of H/L lands on the root exactly when L is
    // tight, and past it by the rounding of H, so t is usually a few ulps
    // beyond: one probe ε back confirms it; else bisection narrows the
    // bracket to 2ε, which is settled (above). The tape in use holds from
    // `box_from` (the segment's start) on; before it, the full tape does.
    const auto crossing_before = [&](double t, double eps, double box_from) -> Crossing {
        // f ≤ 0 where the march starts, or just past a pole: a root only if f is 0 there.
        if (!(t > clear_to)) return {t, false, t};
        if (clear_to < box_from) h.use_full_tape();
        double lo = clear_to, hi = t;
        if (const double back = t - eps; back > lo) {
            const double f = value_at(back);
            if (std::isnan(f)) return {};
            (f > 0.0 ? lo : hi) = back;
        }
        for (int i = 0; i < 128 && hi - lo > 2.0 * eps; ++i) {
            const double mid = 0.5 * lo + 0.5 * hi;
            const double f = value_at(mid);
            if (std::isnan(f)) return {};
            (f > 0.0 ? lo : hi) = mid;
        }
        return settle(lo, hi);
    };
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    for (long visited = 0; !segments.empty(); ++visited) {
        if (visited == settings_.max_segments || counters.over_limit()) return {std::nullopt, true};
        const Segment segment = segments.pop();
        const auto [a, b, depth] = segment;
        const double eps = step_epsilon(h, std::max(std::abs(a), std::abs(b)));

        // Fig. 9, step 2 — and the tape pruned to this segment. The box
        // reaches 2ε past b, where a hit is confirmed (below).
        const Interval enclosure = h.prune(depth, a, b + 2.0 * eps, counters);
        const Interval value = side > 0.0 ? enclosure : -enclosure;
        if (value.is_empty()) {  // f is undefined (NaN) all over this segment
            h.note_nan(h.ray().at(0.5 * (a + b)), counters);
            return {};
        }
        if (value.lo > 0.0) continue;

        // How fast side·H can fall on [a, b]: side·H(t) ≥ side·H(s) −
        // descent·(t − s) for s ≤ t there. Only a fall can reach the
        // surface, so this one-sided bound serves as Lip H does in Fig. 12,
        // and is never larger; 0 when side·H cannot fall — a shadow ray
        // leaving a lit surface, say — and then one step clears the segment.
        segment_a = a, segment_b = b;
        segment_slope = h.slope(a, b, counters);
        const Interval side_segment_slope = side > 0.0 ? segment_slope : -segment_slope;
        const double descent = std::max(0.0, -side_segment_slope.lo);
        const bool falls_throughout = side_segment_slope.hi < 0.0;  // side·H strictly decreasing on [a, b]
        const bool splittable = b - a > 2.0 * eps && segments.can_split(segment);
        if (!std::isfinite(descent)) {
            if (splittable) {
                segments.split(segment, a);
                continue;
            }
            // An ε-segment whose slope has no finite bound (e.g. sqrt at 0):
            // only a sign change at its ends shows a root — unless it is a
            // pole, where f changes sign without one (−1/x at x = 0).
            const double fa = value_at(a);
            if (std::isnan(fa)) return {};
            if (fa <= 0.0) return crossing_before(a, eps, a);
            clear_to = a;
            const double fb = value_at(b);
            if (std::isnan(fb)) return {};
            if (fb <= 0.0) {
                const bool unbounded = !std::isfinite(value.lo) || !std::isfinite(value.hi);
                if (unbounded && closes_in_on_a_pole(h, a, b, counters)) {
                    // The sign changed across a pole, not a root: never look
                    // back past it, and look on for where H comes back to 0.
                    clear_to = b;
                    side = -side;
                    continue;
                }
                return settle(a, b);  // an ε-segment
            }
            if (const auto gap = first_root_in(a, b)) return *gap;
            continue;
        }
        double t = a;
        double t_before = t, f_before = std::numeric_limits<double>::quiet_NaN();  // the step before, if any
        int probes_left = max_probes;
        for (int steps = 0;; ++steps) {
            const double f = value_at(t);
            if (std::isnan(f)) return {};
            if (f <= 0.0) return crossing_before(t, eps, a);  // on or inside the surface
            clear_to = t;
            // Closing in by steps is slow: each takes a share of what is left
            // (the share the true slope is of the bound), so reaching ε took
            // about ten steps a hit on the bear at 512². The last two steps'
            // secant predicts where H reaches 0 (Newton's eq. 22 with a
            // difference slope); the secant's slope is never steeper than the
            // bound, so the prediction is always past the next step. A sign
            // change a little past it, on a stretch where side·H is proven
            // strictly decreasing — by the segment's own slope when that shows
            // it, else by one over the stretch — brackets its one root there,
            // the first, as all before t is cleared.
            if (probes_left > 0 && f < f_before) {
                const double secant = (f - f_before) / (t - t_before);
                const double probe = t + 1.25 * (-f / secant);
                if (probe <= b) {
                    --probes_left;
                    const double f_probe = value_at(probe);
                    if (std::isnan(f_probe)) return {};
                    if (f_probe <= 0.0 && (falls_throughout || side_slope(t, probe).hi < 0.0)) return {t, false, probe};
                }
            }
            t_before = t, f_before = f;
            if (f < descent * eps) {
                // Fig. 12, step 2a: the distance bound says the surface may be
                // within ε. A sign change just ahead confirms it; otherwise L
                // is too loose here, so tighten it by splitting what is left.
                const double ahead = t + 2.0 * eps;
                const double f_ahead = value_at(ahead);
                if (std::isnan(f_ahead)) return {};
                if (f_ahead <= 0.0) return settle(t, ahead);
                if (const auto gap = first_root_in(t, ahead)) return *gap;
                if (b - ahead > 2.0 * eps && segments.can_split(segment)) {
                    segments.split(segment, ahead);
                    break;
                }
                t = ahead;
                if (t >= b) break;
                continue;
            }
            if (descent == 0.0) break;  // side·H > 0 at t and never falls: this segment is clear
            t += f / descent;           // D(t) = H(t) / Lip H, at least ε
            if (t >= b) break;          // this segment is clear
            if (steps >= settings_.steps_before_split && b - t > 2.0 * eps && segments.can_split(segment)) {
                segments.split(segment, t);
                break;
            }
        }
    }
    return {};
}

}  // namespace zeroset
