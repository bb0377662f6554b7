// Sphere tracing with per-segment Lipschitz bounds (see sphere_tracer.hpp).
#include "zeroset/trace/sphere_tracer.hpp"

#include <array>
#include <cmath>

namespace zeroset {

namespace {

/// Segments waiting to be marched, front of the ray on top. Splitting pushes
/// two halves for one popped segment, so the depth grows by one per halving;
/// a segment is split only while the stack has room (otherwise it is simply
/// marched with the bound it has, which is still safe).
class SegmentStack {
public:
    void push(double a, double b) { items_[size_++] = {a, b}; }
    [[nodiscard]] bool has_room_for_split() const { return size_ + 2 <= items_.size(); }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    Span pop() { return items_[--size_]; }

private:
    std::array<Span, 128> items_{};
    std::size_t size_ = 0;
};

}  // namespace

SphereTracer::SphereTracer(const Tape& tape, SphereTraceSettings settings)
    : settings_(settings), point_(tape), box_(tape) {}

LipschitzBound SphereTracer::bound_segment(const Ray& ray, double a, double b, TraceCounters& counters) {
    ++counters.interval_evaluations;
    const Vec3d pa = ray.at(a), pb = ray.at(b);
    return lipschitz_bound(box_, Box3{min(pa, pb), max(pa, pb)});
}

std::optional<double> SphereTracer::first_hit(const Ray& ray, Span span, TraceCounters& counters) {
    const double eps = settings_.epsilon;
    SegmentStack segments;
    segments.push(span.t0, span.t1);
    while (!segments.empty()) {
        const auto [a, b] = segments.pop();
        const LipschitzBound bound = bound_segment(ray, a, b, counters);
        if (bound.value.is_empty()) {  // f is undefined (NaN) all over this segment
            ++counters.nan_evaluations;
            last_nan_point_ = ray.at(0.5 * (a + b));
            return std::nullopt;
        }
        if (bound.value.lo > 0.0) continue;  // no surface here
        const double lipschitz = bound.constant;
        const bool splittable = b - a > 2.0 * eps && segments.has_room_for_split();
        if (!std::isfinite(lipschitz)) {
            if (splittable) {
                const double mid = 0.5 * (a + b);
                segments.push(mid, b);
                segments.push(a, mid);
                continue;
            }
            return a;  // an unbounded slope inside an ε-segment that may hold the surface
        }
        double t = a;
        for (int steps = 0;; ++steps) {
            const Vec3d p = ray.at(t);
            const double h = point_(p.x, p.y, p.z);
            ++counters.point_evaluations;
            if (std::isnan(h)) {
                ++counters.nan_evaluations;
                last_nan_point_ = p;
                return std::nullopt;
            }
            if (h <= lipschitz * eps) return t;  // Fig. 12, step 2a: within ε of the surface
            t += h / lipschitz;                  // D(t) = H(t) / Lip H
            if (t >= b) break;                   // this segment is clear
            if (steps >= settings_.steps_before_split && b - t > 2.0 * eps && segments.has_room_for_split()) {
                const double mid = 0.5 * (t + b);
                segments.push(mid, b);
                segments.push(t, mid);
                break;
            }
        }
    }
    return std::nullopt;
}

}  // namespace zeroset
