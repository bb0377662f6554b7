// Evaluations along one ray, on the full tape or a pruned one.
#include "zeroset/trace/ray_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

RayFunction::RayFunction(const Tape& tape)
    : tape_(&tape), point_(tape), jet_(tape), value_enclosure_(tape), enclosure_(tape), slope_(tape), bound_(&tape),
      base_(&tape),
      can_prune_(tape.has_choices()),
      base_can_prune_(can_prune_) {}

void RayFunction::set_ray(const Ray& ray) {
    ray_ = ray;
    focus_ = std::numeric_limits<double>::quiet_NaN();
    known_ = {};
    dir_length_known_ = false;
    reset_base_tape();
}

double RayFunction::measured_dir_length() const {
    const double length = std::hypot(ray_.dir.x, ray_.dir.y, ray_.dir.z);  // no underflow for tiny directions
    return length > 0.0 ? rounding::up(length) : 0.0;
}

void RayFunction::set_base_tape(const Tape& tape, bool can_prune) {
    base_ = &tape;
    base_can_prune_ = can_prune;
    valid_depths_ = 0;
    use_full_tape();
}

double RayFunction::value(double t, TraceCounters& counters) {
    // Asked again at the same t — where one octree cell's method starts as
    // the last one ended, or where a march starts after the method looked —
    // H is the same: every tape pruned from the full one computes the same
    // value there (pruning only drops the losing sides of a min or max).
    if (const std::optional<double> known = known_value(t)) return *known;
    ++counters.point_evaluations;
    const Vec3d p = ray_.at(t);
    const double h = checked(point_.on(bound_, tape_version_)(p.x, p.y, p.z), t, counters);
    if (h == h) known_ = {KnownValue{t, h}, known_[0]};  // a NaN is evaluated (and recorded) again
    return h;
}

Jet<double> RayFunction::jet(double t, TraceCounters& counters) {
    ++counters.point_evaluations;
    Jet<double> j = evaluate_along_ray(jet_.on(bound_, tape_version_), ray_.origin, ray_.dir, t);
    j.v = checked(j.v, t, counters);
    return j;
}

Interval RayFunction::enclose_value(double t, TraceCounters& counters) {
    ++counters.interval_evaluations;
    const Interval ti(t);
    const auto coordinate = [&ti](double o, double d) { return Interval(o) + Interval(d) * ti; };
    return value_enclosure_.on(bound_, tape_version_)(coordinate(ray_.origin.x, ray_.dir.x), coordinate(ray_.origin.y, ray_.dir.y),
                            coordinate(ray_.origin.z, ray_.dir.z));
}

Jet<Interval> RayFunction::enclose(double a, double b, TraceCounters& counters) {
    ++counters.interval_evaluations;
    Jet<Interval> j = evaluate_along_ray(enclosure_.on(bound_, tape_version_), ray_.origin, ray_.dir, Interval(a, b));
    if (j.v.is_empty()) note_nan(ray_.at(0.5 * (a + b)), counters);  // undefined all over the segment
    return j;
}

// Flattened: the interval products and quotients of the dual numbers are
// inlined into the tape walk instead of called once an operation.
[[gnu::flatten]] Interval RayFunction::slope(double a, double b, TraceCounters& counters) {
    ++counters.gradient_evaluations;
    // H′(t) = ∇f·x_d at a point of the segment, so the enclosure of ∇f·x_d
    // over the segment's box holds H′ there: one derivative carried instead
    // of three, and no |∇f|·|x_d| (Cauchy–Schwarz) in between.
    const Box3 box = segment_box(a, b);
    const auto along = [&](int axis) {
        return DirectionalDual<Interval>(Interval(box.lo[axis], box.hi[axis]), Interval(ray_.dir[axis]));
    };
    const DirectionalDual<Interval> h = slope_.on(bound_, tape_version_)(along(0), along(1), along(2));
    if (h.v.is_empty()) return Interval(0.0);  // undefined all over: nothing to step over
    // An empty derivative where the value is defined: the enclosure lost track of it.
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (h.g.is_empty() || h.g.lo != h.g.lo || h.g.hi != h.g.hi) return {-inf, inf};
    return h.g;
}

Box3 RayFunction::segment_box(double a, double b) const {
    const auto coordinate = [a, b](double o, double d) { return Interval(o) + Interval(d) * Interval(a, b); };
    const Interval cx = coordinate(ray_.origin.x, ray_.dir.x), cy = coordinate(ray_.origin.y, ray_.dir.y),
                   cz = coordinate(ray_.origin.z, ray_.dir.z);
    return {{cx.lo, cy.lo, cz.lo}, {cx.hi, cy.hi, cz.hi}};
}

Interval RayFunction::prune(std::size_t depth, double a, double b, TraceCounters& counters) {
    ++counters.interval_evaluations;
    if (!pruner_) {
        pruner_.emplace(*tape_);
        pruned_.resize(SegmentStack::max_depth);
        tape_at_.resize(SegmentStack::max_depth);
    }
    // The parent is the tape of the enclosing segment, pruned at depth − 1
    // on this ray; without one (a first prune deeper than 0) the base tape.
    const Tape& parent = depth == 0 || depth > valid_depths_ ? *base_ : *tape_at_[depth - 1];
    const Interval f = pruner_->evaluate(parent, segment_box(a, b));
    // Where f keeps one sign the caller has no root to look for, and
    // rarely evaluates anything: the parent's tape serves, unpruned.
    const bool one_sign = f.lo > 0.0 || f.hi < 0.0;
    const Tape& tape = one_sign ? parent : pruner_->simplified(pruned_[depth]);
    tape_at_[depth] = &tape;
    use_tape(tape, &tape == &pruned_[depth]);  // rewritten in place: new clauses and constants
    valid_depths_ = depth + 1;  // deeper entries belonged to other segments
    return f;
}

void RayFunction::note_nan(const Vec3d& p, TraceCounters& counters) {
    ++counters.nan_evaluations;
    last_nan_point_ = p;
}

}  // namespace zeroset
