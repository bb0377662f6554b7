// Bounds: the region an object's surface is known to lie in — a box or a
// sphere (survey §6.1). Rays are clipped to it before root finding, and the
// Lipschitz bound is computed over its enclosing box. Only a plane may have
// none (Kind::None): no method could search an infinite span.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "zeroset/math/box3.hpp"
#include "zeroset/math/power_of_two.hpp"

namespace zeroset {

/// Whether a sphere against a ray needs no scaling: its lengths — the larger
/// of radius and offset, `k`, and the direction's largest component, `m` —
/// between 2^−250 and 2^250. Then b² and a·c of its quadratic, products of
/// four lengths, stay within 2^±1000, normal doubles, and scaling by powers
/// of two would change no bit of the result (it would only move where a
/// component 2^−600 of the largest turns subnormal).
constexpr bool sphere_lengths_are_ordinary(double k, double m) {
    constexpr double tiny = 0x1p-250, huge = 0x1p250;
    return k > tiny && k < huge && m > tiny && m < huge;
}

struct Bounds {
    enum class Kind { Box, Sphere, None };
    Kind kind = Kind::Box;
    Box3 box{{-1, -1, -1}, {1, 1, 1}};  // Kind::Box
    Vec3d center{};                     // Kind::Sphere
    double radius = 1.0;                // Kind::Sphere

    static Bounds make_box(const Box3& b) {
        Bounds bounds;
        bounds.box = b;
        return bounds;
    }
    static Bounds make_sphere(const Vec3d& c, double r) {
        Bounds bounds;
        bounds.kind = Kind::Sphere;
        bounds.center = c;
        bounds.radius = r;
        return bounds;
    }

    static Bounds none() {
        Bounds bounds;
        bounds.kind = Kind::None;
        return bounds;
    }

    /// The outward normal at a point on the bounds: a sphere's, or that of
    /// the box face the point is nearest to (relative to the box's size).
    [[nodiscard]] Vec3d normal_at(const Vec3d& p) const {
        if (kind == Kind::Sphere) return (p - center) / radius;
        int best_axis = 0;
        double best = std::numeric_limits<double>::infinity(), sign = 1.0;
        for (int axis = 0; axis < 3; ++axis) {
            const double size = std::max(box.hi[axis] - box.lo[axis], 1e-300);
            const double to_lo = std::abs(p[axis] - box.lo[axis]) / size, to_hi = std::abs(box.hi[axis] - p[axis]) / size;
            if (to_lo < best) best = to_lo, best_axis = axis, sign = -1.0;
            if (to_hi < best) best = to_hi, best_axis = axis, sign = 1.0;
        }
        Vec3d n;
        n[best_axis] = sign;
        return n;
    }

    /// The smallest axis-aligned box containing the bounds.
    [[nodiscard]] Box3 enclosing_box() const {
        constexpr double inf = std::numeric_limits<double>::infinity();
        if (kind == Kind::None) return {{-inf, -inf, -inf}, {inf, inf, inf}};
        if (kind == Kind::Box) return box;
        const Vec3d r{radius, radius, radius};
        return {center - r, center + r};
    }

    /// The part of [t_min, t_max] where the ray is inside the bounds, if any.
    [[nodiscard]] std::optional<Span> clip(const Ray& ray, double t_min, double t_max) const {
        if (kind == Kind::None) return Span{t_min, t_max};
        if (kind == Kind::Box) return box.clip(ray, t_min, t_max);
        // |o + t·d − c|² = r²  →  a t² + 2 b t + c = 0, with lengths in units
        // of the power of two 2^ek nearest below max(r, |o − c|) and d in
        // units of 2^em below its largest component, so that no square
        // overflows or underflows (r = 10³⁰⁰ is valid) and, the scaling being
        // exact, ordinary spheres clip exactly as without it.
        const Vec3d offset = ray.origin - center;
        const double k = std::max(radius, max_abs(offset)), m = max_abs(ray.dir);
        if (!(m > 0.0) || !(k > 0.0) || !std::isfinite(k) || !std::isfinite(m)) return std::nullopt;
        const bool ordinary = sphere_lengths_are_ordinary(k, m);
        const int ek = ordinary ? 0 : binary_exponent(k), em = ordinary ? 0 : binary_exponent(m);
        const auto scaled = [ordinary](const Vec3d& v, int e) {
            return ordinary ? v : Vec3d{times_power_of_two(v.x, -e), times_power_of_two(v.y, -e), times_power_of_two(v.z, -e)};
        };
        const Vec3d oc = scaled(offset, ek), d = scaled(ray.dir, em);
        const double r = ordinary ? radius : times_power_of_two(radius, -ek);
        const double a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - r * r;
        const double disc = b * b - a * c;
        if (disc < 0.0) return std::nullopt;
        const double s = std::sqrt(disc);
        // Numerically stable pair of roots, in t = t' · k / m.
        const double q = b >= 0.0 ? -(b + s) : -(b - s);
        double t0 = ordinary ? q / a : times_power_of_two(q / a, ek - em);
        double t1 = q != 0.0 ? c / q : q / a;
        if (!ordinary) t1 = times_power_of_two(t1, ek - em);
        if (std::isnan(t0) || std::isnan(t1)) return std::nullopt;  // 0 · ∞: a tangent ray with a tiny direction
        if (t0 > t1) std::swap(t0, t1);
        t0 = std::max(t0, t_min);
        t1 = std::min(t1, t_max);
        if (t0 > t1) return std::nullopt;
        return Span{t0, t1};
    }
};

/// The size a gated object's tolerances and offsets follow: its search
/// region's (`region_scale`), or the gate's diagonal when that is smaller —
/// a gated sheet is searched in the ±10⁴ box, but what is seen of it lies
/// about the gate.
inline double gated_scale(double region_scale, const std::optional<Bounds>& gate) {
    return gate ? std::min(region_scale, gate->enclosing_box().diagonal()) : region_scale;
}

/// A ray against an object's gate (LeafDescription::gate): nothing when it
/// misses it — tested, as POV-Ray's bounded_by, from the ray's start
/// (t = 0, not a later t_min, which a CSG node moves up for its later
/// children) and without end, so a shadow ray that meets it only beyond its
/// light still counts — else where the gated surface most likely lies along
/// the ray: its nearest approach to the gate's centre, within the gate.
inline std::optional<double> gate_focus(const Bounds& gate, const Ray& ray, double t_min) {
    const double from = std::min(t_min, 0.0);
    if (gate.kind == Bounds::Kind::Sphere) {
        // Whether the ray leaves the sphere at or after `from` needs no square
        // root, and the nearest approach, −b/a, is the chord's middle, so it
        // lies in the chord: of the clamp only `from` is left. Every ray asks
        // this, and the clip's root and divisions were a tenth of a gated
        // sheet's render. Lengths of ordinary size only, as in Bounds::clip.
        const Vec3d oc = ray.origin - gate.center;
        if (sphere_lengths_are_ordinary(std::max(gate.radius, max_abs(oc)), max_abs(ray.dir))) {
            const double a = dot(ray.dir, ray.dir), b = dot(oc, ray.dir), c = dot(oc, oc) - gate.radius * gate.radius;
            const double disc = b * b - a * c;
            if (!(disc >= 0.0)) return std::nullopt;  // the line passes the sphere by
            // The exit, (−b + √disc)/a, is before `from` when a·from + b > √disc.
            const double past = a * from + b;
            if (past > 0.0 && past * past > disc) return std::nullopt;
            return std::max(-b / a, from);
        }
    }
    const auto in_gate = gate.clip(ray, from, std::numeric_limits<double>::infinity());
    if (!in_gate) return std::nullopt;
    const Vec3d centre = gate.enclosing_box().center();
    const double nearest = -dot(ray.origin - centre, ray.dir) / dot(ray.dir, ray.dir);
    return std::clamp(nearest, in_gate->t0, in_gate->t1);
}


}  // namespace zeroset
