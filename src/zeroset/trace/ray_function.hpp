// RayFunction: the surface seen along one ray, H(t) = f(x_o + t·x_d) (survey
// eqs. 7 and 13), in every form the intersection methods need — H at a point,
// H with H′ and H″ at a point (eqs. 19–21), and enclosures of H, H′, H″ over
// a whole segment of t (Fig. 9 needs H′, Fig. 11 needs H″). It counts what it
// evaluates, so methods can be compared on the same ray.
#pragma once

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/ray.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

class RayFunction {
public:
    explicit RayFunction(const Tape& tape) : point_(tape), jet_(tape), value_enclosure_(tape), enclosure_(tape) {}

    void set_ray(const Ray& ray) { ray_ = ray; }
    [[nodiscard]] const Ray& ray() const { return ray_; }

    /// H(t).
    double value(double t, TraceCounters& counters) {
        ++counters.point_evaluations;
        const Vec3d p = ray_.at(t);
        return checked(point_(p.x, p.y, p.z), t, counters);
    }
    /// H(t), H′(t), H″(t).
    Jet<double> jet(double t, TraceCounters& counters) {
        ++counters.point_evaluations;
        Jet<double> j = evaluate_along_ray(jet_, ray_.origin, ray_.dir, t);
        j.v = checked(j.v, t, counters);
        return j;
    }
    /// An enclosure of H(t) at one t, free of rounding doubts (the point
    /// x_o + t·x_d itself is enclosed, not rounded).
    Interval enclose_value(double t, TraceCounters& counters) {
        ++counters.interval_evaluations;
        const Interval ti(t);
        const auto coordinate = [&ti](double o, double d) { return Interval(o) + Interval(d) * ti; };
        return value_enclosure_(coordinate(ray_.origin.x, ray_.dir.x), coordinate(ray_.origin.y, ray_.dir.y),
                                coordinate(ray_.origin.z, ray_.dir.z));
    }
    /// Enclosures of H, H′ and H″ over t ∈ [a, b].
    Jet<Interval> enclose(double a, double b, TraceCounters& counters) {
        ++counters.interval_evaluations;
        Jet<Interval> j = evaluate_along_ray(enclosure_, ray_.origin, ray_.dir, Interval(a, b));
        if (j.v.is_empty()) note_nan(ray_.at(0.5 * (a + b)), counters);  // undefined all over the segment
        return j;
    }

    /// Records that H is NaN at p (counted in TraceCounters::nan_evaluations).
    void note_nan(const Vec3d& p, TraceCounters& counters) {
        ++counters.nan_evaluations;
        remember_nan_point(p);
    }
    /// Remembers a NaN that someone else already counted.
    void remember_nan_point(const Vec3d& p) { last_nan_point_ = p; }
    /// Where H last evaluated to NaN.
    [[nodiscard]] const Vec3d& last_nan_point() const { return last_nan_point_; }

private:
    double checked(double value, double t, TraceCounters& counters) {
        if (value != value) note_nan(ray_.at(t), counters);
        return value;
    }

    Vec3d last_nan_point_{};
    Ray ray_{};
    Evaluator<double> point_;
    Evaluator<Jet<double>> jet_;
    Evaluator<Interval> value_enclosure_;
    Evaluator<Jet<Interval>> enclosure_;
};

}  // namespace zeroset
