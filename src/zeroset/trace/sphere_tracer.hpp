// Sphere tracing (the survey's §5.2, Fig. 12): march along the ray in steps
// D(t) = H(t)/L that cannot pass the surface, where L bounds |∇f| — and so
// |H′| for a unit direction — over the part of space the step stays in.
//
// L is never a user parameter. It is the interval enclosure of ∇f over the
// axis-aligned box around the ray segment being marched (expr/lipschitz.hpp).
// The span inside the object's bounds is the first segment; a segment whose
// bound is infinite or loose (many steps without a hit) is split in two and
// each half gets its own, tighter L. On every segment:
//   - the interval enclosure of f decides first: a segment where f > 0 holds
//     no surface and is skipped whole (Fig. 9, step 2); one where f is
//     undefined everywhere is a NaN error;
//   - the tape is pruned to the clauses live in the segment's box
//     (expr/tape_pruner.hpp), and the halves of a split segment prune their
//     parent's tape further, so deep in a CSG model a step walks a few clauses;
//   - a hit is reported only where the distance bound drops below ε and f
//     changes sign within 2ε ahead.
// Every step stays in a segment whose L holds, so the first hit is never
// stepped over; every step or split makes progress of at least ε, so the
// march always ends.
#pragma once

#include <optional>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/expr/tape_pruner.hpp"
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
    /// `tape` must use SlotLayout::OnePerValue (it is pruned per segment).
    SphereTracer(const Tape& tape, SphereTraceSettings settings);

    /// The smallest t in span at which the ray (unit direction) meets the
    /// surface, to within settings.epsilon; nothing if it does not. The
    /// surface is crossed in [t, t + 2ε].
    std::optional<double> first_hit(const Ray& ray, Span span, TraceCounters& counters) {
        return first_crossing(ray, span, 1.0, counters);
    }
    /// The same for the function side·f: with side = −1, the first point
    /// where a ray inside the solid leaves it.
    std::optional<double> first_crossing(const Ray& ray, Span span, double side, TraceCounters& counters);

    [[nodiscard]] const SphereTraceSettings& settings() const { return settings_; }
    /// Where f last evaluated to NaN (counted in TraceCounters::nan_evaluations).
    [[nodiscard]] const Vec3d& last_nan_point() const { return last_nan_point_; }

private:
    /// side·f at ray.at(t) on the current pruned tape; a NaN is counted and its point remembered.
    double value_at(const Ray& ray, double t, TraceCounters& counters);

    SphereTraceSettings settings_;
    const Tape* tape_;
    TapePruner pruner_;
    std::vector<Tape> pruned_;  // pruned_[d]: the tape of the segment being marched at split depth d
    Evaluator<double> point_;
    Evaluator<Dual<Interval>> slope_;  // f and ∇f over a box
    Vec3d last_nan_point_{};
    double side_ = 1.0;
};

}  // namespace zeroset
