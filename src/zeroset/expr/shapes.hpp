// Distance functions of the classic primitives, as expressions at a point p
// (after Quilez, "distance functions", iquilezles.org/articles/distfunctions,
// rewritten with the op table's ops). Each is negative inside, zero on the
// surface and — except the ellipsoid — the exact signed Euclidean distance,
// so |∇f| = 1 wherever it is differentiable. Every shape is centred at the
// origin; those with an axis (cylinder, cone, torus) have it along z. Move
// them with expr/deform.hpp, or evaluate them at a transformed point.
//
// Norms are built with hypot, whose derivative enclosure stays within the
// unit ball even where the norm's argument is 0 — length(max(q, 0)) of a box
// is 0 all over its inside, where √(q·q) would make ∇f = 0/0 and interval
// Lipschitz bounds infinite.
//
// A parameter that makes no shape (a radius ≤ 0, …) throws
// std::invalid_argument with a message naming it.
#pragma once

#include "zeroset/expr/substitute.hpp"

namespace zeroset {

/// |p|, as hypot(hypot(x, y), z).
Expr norm(const ExprPoint& p);

/// A ball of radius r > 0: |p| − r.
Expr sd_sphere(const ExprPoint& p, double radius);
/// An axis-aligned box with half-extents b > 0: with q = |p| − b,
/// |max(q, 0)| + min(max(q.x, q.y, q.z), 0).
Expr sd_box(const ExprPoint& p, const Vec3d& half_size);
/// The box of half-extents b with its edges and corners rounded by r,
/// 0 < r ≤ min(b): the box of half-extents b − r, grown by r.
Expr sd_round_box(const ExprPoint& p, const Vec3d& half_size, double radius);
/// A capped cylinder around z, radius r > 0, from z = −h to z = h (h > 0):
/// with d = (ρ − r, |z| − h), ρ = |(x, y)|, min(max(d₁, d₂), 0) + |max(d, 0)|.
Expr sd_cylinder(const ExprPoint& p, double radius, double half_height);
/// A capped cone (frustum) around z from z = −h (radius r_bottom) to z = h
/// (radius r_top); radii ≥ 0, not both 0. In the meridian plane (ρ, z) it is
/// the distance to the trapezoid's three boundary segments (bottom cap, top
/// cap, side), signed by the trapezoid's planes: with e the unsigned distance
/// and s = max(|z| − h, side plane) (≤ 0 inside, where then e = −s),
/// f = e + 2 min(s, 0).
Expr sd_capped_cone(const ExprPoint& p, double half_height, double r_bottom, double r_top);
/// The capsule around the segment a–b, radius r > 0: the distance to the
/// segment minus r (a sphere when a = b).
Expr sd_capsule(const ExprPoint& p, const Vec3d& a, const Vec3d& b, double radius);
/// A torus around z in the plane z = 0: the tube of radius r > 0 around the
/// circle of radius R > 0, |(ρ − R, z)| − r.
Expr sd_torus(const ExprPoint& p, double major_radius, double minor_radius);
/// The half-space below the plane p·n̂ = offset (n̂ = normal/|normal|):
/// p·n̂ − offset.
Expr sd_plane(const ExprPoint& p, const Vec3d& normal, double offset);
/// An axis-aligned ellipsoid with semi-axes r > 0 — NOT an exact distance:
/// min(r)·(|p/r| − 1), which is 0 exactly on the ellipsoid, negative inside,
/// 1-Lipschitz and at most the distance in magnitude (a distance bound; it
/// underestimates by up to the factor min(r)/max(r) away from the surface).
/// Quilez's tighter k₀(k₀ − 1)/k₁ is 0/0 at the centre, so it is not used.
Expr sd_ellipsoid(const ExprPoint& p, const Vec3d& radii);

}  // namespace zeroset
