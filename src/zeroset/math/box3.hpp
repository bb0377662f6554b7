// Box3: an axis-aligned box, the usual bounding volume of an implicit object
// (survey §6.1), with the ray slab test that clips a ray to it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "zeroset/math/ray.hpp"

namespace zeroset {

/// A parameter span [t0, t1] along a ray.
struct Span {
    double t0;
    double t1;
};

struct Box3 {
    Vec3d lo;
    Vec3d hi;

    [[nodiscard]] constexpr Vec3d center() const { return (lo + hi) * 0.5; }
    [[nodiscard]] constexpr Vec3d size() const { return hi - lo; }
    /// The diagonal's length, without overflow for any finite box.
    [[nodiscard]] double diagonal() const {
        const Vec3d s = size();
        return std::hypot(s.x, s.y, s.z);
    }
    [[nodiscard]] constexpr bool contains(const Vec3d& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }
    [[nodiscard]] constexpr bool valid() const { return lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z; }

    /// The part of [t_min, t_max] where the ray is inside the box, if any (slab test).
    [[nodiscard]] std::optional<Span> clip(const Ray& ray, double t_min, double t_max) const {
        double t0 = t_min, t1 = t_max;
        for (int axis = 0; axis < 3; ++axis) {
            const double o = ray.origin[axis], d = ray.dir[axis];
            if (d == 0.0) {
                if (o < lo[axis] || o > hi[axis]) return std::nullopt;
                continue;
            }
            double a = (lo[axis] - o) / d, b = (hi[axis] - o) / d;
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        // Tested once, not per axis: the span only narrows, and the three
        // axes' divisions overlap without a branch between them.
        if (t0 > t1) return std::nullopt;
        return Span{t0, t1};
    }
};

/// The box holding nothing: the identity of united().
constexpr Box3 empty_box() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{inf, inf, inf}, {-inf, -inf, -inf}};
}
/// The smallest box holding both.
constexpr Box3 united(const Box3& a, const Box3& b) { return {min(a.lo, b.lo), max(a.hi, b.hi)}; }
/// The part both hold (not valid() when they do not meet).
constexpr Box3 overlap(const Box3& a, const Box3& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

}  // namespace zeroset
