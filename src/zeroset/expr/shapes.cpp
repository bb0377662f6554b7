// The primitives' distance expressions (formulas in shapes.hpp).
#include "zeroset/expr/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/parameter_checks.hpp"

namespace zeroset {

namespace {

using parameter_checks::require_positive;
using parameter_checks::shown;

/// p·c without the terms whose coefficient is 0.
Expr dot_with(const ExprPoint& p, const Vec3d& c) {
    Expr r(0.0);
    for (int i = 0; i < 3; ++i)
        if (c[i] != 0.0) r = r + (c[i] == 1.0 ? p[i] : c[i] * p[i]);
    return r;
}

/// The exact signed distance of an axis-aligned box of half-extents b, given
/// q = |p| − b (Quilez's sdBox).
Expr box_from_q(const ExprPoint& q) {
    const Expr outside = norm({max(q.x, 0.0), max(q.y, 0.0), max(q.z, 0.0)});
    return outside + min(max(max(q.x, q.y), q.z), 0.0);
}

}  // namespace

Expr norm(const ExprPoint& p) { return hypot(hypot(p.x, p.y), p.z); }

Expr sd_sphere(const ExprPoint& p, double radius) {
    require_positive(radius, "the radius");
    return norm(p) - radius;
}

Expr sd_box(const ExprPoint& p, const Vec3d& half_size) {
    require_positive(half_size, "the half size");
    return box_from_q({abs(p.x) - half_size.x, abs(p.y) - half_size.y, abs(p.z) - half_size.z});
}

Expr sd_round_box(const ExprPoint& p, const Vec3d& half_size, double radius) {
    require_positive(half_size, "the half size");
    require_positive(radius, "the radius");
    const double smallest = std::min({half_size.x, half_size.y, half_size.z});
    if (radius > smallest)
        throw std::invalid_argument("the radius must be at most the smallest half size " + shown(smallest) +
                                    ", but it is " + shown(radius));
    const Vec3d inner = half_size - Vec3d{radius, radius, radius};
    return box_from_q({abs(p.x) - inner.x, abs(p.y) - inner.y, abs(p.z) - inner.z}) - radius;
}

Expr sd_cylinder(const ExprPoint& p, double radius, double half_height) {
    require_positive(radius, "the radius");
    require_positive(half_height, "the half height");
    const Expr d1 = hypot(p.x, p.y) - radius, d2 = abs(p.z) - half_height;
    return min(max(d1, d2), 0.0) + hypot(max(d1, 0.0), max(d2, 0.0));
}

Expr sd_capped_cone(const ExprPoint& p, double half_height, double r_bottom, double r_top) {
    require_positive(half_height, "the half height");
    if (!(r_bottom >= 0.0) || !(r_top >= 0.0) || !std::isfinite(r_bottom) || !std::isfinite(r_top) ||
        r_bottom + r_top == 0.0)
        throw std::invalid_argument("the radii must be at least 0 and not both 0, but they are " + shown(r_bottom) +
                                    " and " + shown(r_top));
    const double h = half_height;
    const Expr rho = hypot(p.x, p.y), z = p.z;
    // The side from A = (r_bottom, −h) to B = (r_top, h) in the meridian plane.
    const double ex = r_top - r_bottom, ez = 2.0 * h, length2 = ex * ex + ez * ez, length = std::sqrt(length2);
    const Expr ax = rho - r_bottom, az = z + h;  // the point relative to A
    const Expr along = clamp((ax * ex + az * ez) / length2, 0.0, 1.0);
    const Expr side = hypot(ax - along * ex, az - along * ez);
    const Expr bottom = hypot(max(rho - r_bottom, 0.0), az);
    const Expr top = hypot(max(rho - r_top, 0.0), z - h);
    const Expr unsigned_distance = min(min(bottom, top), side);
    const Expr planes = max(abs(z) - h, (ax * ez - az * ex) / length);
    return unsigned_distance + 2.0 * min(planes, 0.0);
}

Expr sd_capsule(const ExprPoint& p, const Vec3d& a, const Vec3d& b, double radius) {
    require_positive(radius, "the radius");
    const ExprPoint pa{p.x - a.x, p.y - a.y, p.z - a.z};
    const Vec3d ba = b - a;
    const double length2 = dot(ba, ba);
    if (length2 == 0.0) return norm(pa) - radius;
    const Expr h = clamp(dot_with(pa, ba) / length2, 0.0, 1.0);
    return norm({pa.x - ba.x * h, pa.y - ba.y * h, pa.z - ba.z * h}) - radius;
}

Expr sd_torus(const ExprPoint& p, double major_radius, double minor_radius) {
    require_positive(major_radius, "the major radius R");
    require_positive(minor_radius, "the minor radius r");
    return hypot(hypot(p.x, p.y) - major_radius, p.z) - minor_radius;
}

Expr sd_plane(const ExprPoint& p, const Vec3d& normal, double offset) {
    const double n = length(normal);
    if (!(n > 0.0) || !std::isfinite(n)) throw std::invalid_argument("the normal must be a nonzero finite vector");
    if (!std::isfinite(offset)) throw std::invalid_argument("the offset must be finite");
    return dot_with(p, normal / n) - offset;
}

Expr sd_ellipsoid(const ExprPoint& p, const Vec3d& radii) {
    require_positive(radii, "the radii");
    const double smallest = std::min({radii.x, radii.y, radii.z});
    return smallest * (norm({p.x / radii.x, p.y / radii.y, p.z / radii.z}) - 1.0);
}

}  // namespace zeroset
