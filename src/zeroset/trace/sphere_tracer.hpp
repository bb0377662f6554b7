// Sphere tracing (the survey's §5.2, Fig. 12): march along the ray in steps
// D(t) = H(t)/L that cannot pass the surface, where L bounds |∇f| — and so
// |H′| for a unit direction — over the part of space the step stays in.
//
// L is never a user parameter. It is the interval enclosure of ∇f over the
// axis-aligned box around the ray segment being marched (expr/lipschitz.hpp).
// The object's whole bounds give the first segment; a segment whose bound is
// infinite or loose (many steps without a hit) is split in two and each half
// gets its own, tighter L. A segment over which the interval enclosure of f
// is positive holds no surface and is skipped whole (Fig. 9, step 2).
// Every step is therefore safe: the first hit is never stepped over.
#pragma once

#include <optional>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

struct SphereTraceSettings {
    /// A hit is reported where the distance bound H/L drops below epsilon.
    double epsilon = 1e-6;
    /// Steps taken in one segment before it is split to tighten its L.
    int steps_before_split = 16;
};

class SphereTracer {
public:
    SphereTracer(const Tape& tape, SphereTraceSettings settings);

    /// The smallest t in span at which the ray (unit direction) meets the
    /// surface, to within settings.epsilon; nothing if it does not.
    std::optional<double> first_hit(const Ray& ray, Span span, TraceCounters& counters);

    [[nodiscard]] const SphereTraceSettings& settings() const { return settings_; }
    /// Where f last evaluated to NaN (counted in TraceCounters::nan_evaluations).
    [[nodiscard]] const Vec3d& last_nan_point() const { return last_nan_point_; }

private:
    static Box3 segment_box(const Ray& ray, double a, double b);
    /// f at ray.at(t); a NaN is counted and its point remembered.
    double value_at(const Ray& ray, double t, TraceCounters& counters);

    SphereTraceSettings settings_;
    Evaluator<double> point_;
    Evaluator<Interval> range_;           // f over a box
    Evaluator<Dual<Interval>> slope_;     // f and ∇f over a box
    Vec3d last_nan_point_{};
};

}  // namespace zeroset
