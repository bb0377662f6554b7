// Sphere tracing (the survey's §5.2, Fig. 12): march along the ray in steps
// D(t) = H(t)/L that cannot pass the surface, where L bounds how fast H can
// fall (−H′, at most |H′|) over the part of the ray the step stays in.
//
// L is never a user parameter. It comes from the interval enclosure of
// H′ = x_d·∇f over the box around the segment being marched
// (RayFunction::slope, eq. 30 along the ray), so it holds for a direction of
// any length — as the rays a transformed primitive passes on have. The span inside the object's bounds is the first
// segment; a segment whose bound is infinite or loose (many steps without a
// hit) is split in two and each half gets its own, tighter L. On every
// segment:
//   - the interval enclosure of f decides first: a segment where f > 0 holds
//     no surface and is skipped whole (Fig. 9, step 2); one where f is
//     undefined everywhere is a NaN error;
//   - the tape is pruned to the clauses live in the segment's box
//     (RayFunction::prune), and the halves of a split segment prune their
//     parent's tape further, so deep in a CSG model a step walks a few clauses;
//   - a hit is reported where the distance bound drops below ε and f
//     changes sign within 2ε ahead — or, sooner, where a probe at the
//     secant's zero (from the last two steps) finds f changed sign on a
//     stretch where f is proven strictly monotone (an enclosure of H′ with
//     one sign): that stretch holds exactly one root, and all before it is
//     cleared, so it is the first. The 2ε bracket may hold three (a sheet
//     thinner than 2ε in front of the crossing): it is proven monotone too,
//     or cleared by steps up to Newton's root, or isolated by intervals;
//   - where the bound drops below ε but f > 0 at both ends of the 2ε ahead
//     (a graze, or a sheet thinner than 2ε), that ε-segment is settled by
//     Mitchell's interval isolation (interval_method.hpp) down to the
//     tangent width, so nothing is passed, however thin — the guarantee of
//     the interval method.
// ε is a length in space; along the ray it is ε/|x_d|, and never less than a
// few units in the last place of t, so that every step moves t. Every step
// stays in a segment whose L holds, so the first hit is never stepped over;
// every step or split makes progress of at least ε, so the march always ends:
// within about 3 × (the span's length in space) / ε segments and steps,
// 3·10⁶ for a ray across the object's bounds — and within `max_segments`
// segments visited (and as many per isolated ε-segment), past which it gives
// up (a pathological function with many near-grazes would otherwise spend
// seconds on one ray); the render's evaluation budget stops both loops too.
#pragma once

#include <optional>

#include "zeroset/math/box3.hpp"
#include "zeroset/trace/ray_function.hpp"

namespace zeroset {

struct SphereTraceSettings {
    /// A hit is reported where the distance bound drops below epsilon (a length in space).
    double epsilon = 1e-6;
    /// Steps taken in one segment before it is split to tighten its L.
    int steps_before_split = 16;
    /// Segments one march may visit before it gives up.
    long max_segments = 1L << 20;
    /// The width (a length in space) down to which an ε-segment that steps
    /// cannot settle is isolated by intervals; a part this narrow that may
    /// still hold a root is a tangent hit, as in the interval method.
    double tangent_width = 1e-10;
};

/// Where a march ended: at a crossing, at none, or given up (past
/// max_segments; also nothing when it met a NaN, which h records). The
/// crossing lies in [t, end], where side·f > 0 at t and ≤ 0 at end: a
/// stretch proven to hold a single root (or, where the march starts on
/// f ≤ 0, [t, t]: a root only if f is 0 there). When `exact`, t is the
/// first root itself, refined or isolated, and end = t.
struct Crossing {
    std::optional<double> t;
    bool gave_up = false;
    double end = 0.0;
    bool exact = false;
};

class SphereTracer {
public:
    explicit SphereTracer(SphereTraceSettings settings) : settings_(settings) {}

    /// Where the ray first meets the surface in span: nothing if it does
    /// not; else the crossing (above), which the caller refines.
    Crossing first_hit(RayFunction& h, Span span, TraceCounters& counters) const {
        return first_crossing(h, span, 1.0, counters);
    }
    /// The same for the function side·f: with side = −1, the first point
    /// where a ray inside the solid leaves it. A NaN is recorded in h (and
    /// counted); then the answer is nothing. h is back on its full tape
    /// when this returns.
    Crossing first_crossing(RayFunction& h, Span span, double side, TraceCounters& counters) const {
        const Crossing crossing = march(h, span, side, counters);
        h.use_full_tape();
        return crossing;
    }

    /// ε along the ray near t: ε/|x_d|, but at least 4 ulps of t.
    [[nodiscard]] double step_epsilon(const RayFunction& h, double t) const;

    [[nodiscard]] const SphereTraceSettings& settings() const { return settings_; }

private:
    Crossing march(RayFunction& h, Span span, double side, TraceCounters& counters) const;

    SphereTraceSettings settings_;
};

}  // namespace zeroset
