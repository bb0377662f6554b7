// Sphere tracing with per-segment Lipschitz bounds and pruned tapes (see
// sphere_tracer.hpp).
#include "zeroset/trace/sphere_tracer.hpp"

#include <cmath>

#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {

Box3 segment_box(const Ray& ray, double a, double b) {
    const Vec3d pa = ray.at(a), pb = ray.at(b);
    return {min(pa, pb), max(pa, pb)};
}

}  // namespace

SphereTracer::SphereTracer(const Tape& tape, SphereTraceSettings settings)
    : settings_(settings), tape_(&tape), pruner_(tape), pruned_(SegmentStack::max_depth), point_(tape), slope_(tape) {}

double SphereTracer::value_at(const Ray& ray, double t, TraceCounters& counters) {
    const Vec3d p = ray.at(t);
    ++counters.point_evaluations;
    const double h = side_ * point_(p.x, p.y, p.z);
    if (std::isnan(h)) {
        ++counters.nan_evaluations;
        last_nan_point_ = p;
    }
    return h;
}

std::optional<double> SphereTracer::first_crossing(const Ray& ray, Span span, double side, TraceCounters& counters) {
    const double eps = settings_.epsilon;
    side_ = side;
    SegmentStack segments;
    segments.push(span.t0, span.t1, 0);
    while (!segments.empty()) {
        const Segment segment = segments.pop();
        const auto [a, b, depth] = segment;

        // Fig. 9, step 2 — and the tape pruned to this segment. The box
        // reaches 2ε past b, where a hit is confirmed (below).
        ++counters.interval_evaluations;
        const Tape& parent = depth == 0 ? *tape_ : pruned_[depth - 1];
        Tape& tape = pruned_[depth];
        const Interval enclosure = pruner_.prune(parent, segment_box(ray, a, b + 2.0 * eps), tape);
        const Interval value = side > 0.0 ? enclosure : -enclosure;
        if (value.is_empty()) {  // f is undefined (NaN) all over this segment
            ++counters.nan_evaluations;
            last_nan_point_ = ray.at(0.5 * (a + b));
            return std::nullopt;
        }
        if (value.lo > 0.0) continue;
        point_.rebind(tape);
        slope_.rebind(tape);

        ++counters.gradient_evaluations;
        const double lipschitz = lipschitz_bound(slope_, segment_box(ray, a, b)).constant;
        const bool splittable = b - a > 2.0 * eps && segments.can_split(segment);
        if (!std::isfinite(lipschitz)) {
            if (splittable) {
                segments.split(segment, a);
                continue;
            }
            // An ε-segment whose slope has no finite bound (e.g. sqrt at 0):
            // only a sign change at its ends shows a root.
            const double fa = value_at(ray, a, counters);
            if (std::isnan(fa)) return std::nullopt;
            if (fa <= 0.0) return a;
            const double fb = value_at(ray, b, counters);
            if (std::isnan(fb)) return std::nullopt;
            if (fb <= 0.0) return b;
            continue;
        }
        double t = a;
        for (int steps = 0;; ++steps) {
            const double h = value_at(ray, t, counters);
            if (std::isnan(h)) return std::nullopt;
            if (h <= 0.0) return t;  // on or inside the surface (only at a segment's start)
            if (h < lipschitz * eps) {
                // Fig. 12, step 2a: the distance bound says the surface may be
                // within ε. A sign change just ahead confirms it; otherwise L
                // is too loose here, so tighten it by splitting what is left.
                const double ahead = t + 2.0 * eps;
                const double h_ahead = value_at(ray, ahead, counters);
                if (std::isnan(h_ahead)) return std::nullopt;
                if (h_ahead <= 0.0) return t;
                if (b - ahead > 2.0 * eps && segments.can_split(segment)) {
                    segments.split(segment, ahead);
                    break;
                }
                t = ahead;  // an ε-segment positive at both ends: at most a sub-ε graze
                if (t >= b) break;
                continue;
            }
            t += h / lipschitz;  // D(t) = H(t) / Lip H
            if (t >= b) break;   // this segment is clear
            if (steps >= settings_.steps_before_split && b - t > 2.0 * eps && segments.can_split(segment)) {
                segments.split(segment, t);
                break;
            }
        }
    }
    return std::nullopt;
}

}  // namespace zeroset
