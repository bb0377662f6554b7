// CameraFrustum::misses: a box it calls missed meets no ray of the tile
// (rays through random points of every pixel, and its corners), and the
// test decides: boxes beside the tile, behind the eye or around it. Its
// distance_outside bounds how near the rays come to a segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "support/camera_tiles.hpp"
#include "zeroset/accel/camera_frustum.hpp"

namespace zeroset {
namespace {

/// A tile of 8 × 6 pixels near the middle of a camera looking along a tilted axis.
CameraFrustum tilted_tile() {
    CameraFrustum f;
    f.origin = {0.3, 1.2, -4.0};
    f.forward = normalize(Vec3d{0.1, -0.25, 1.0});
    f.right = normalize(cross(Vec3d{0, 1, 0}, f.forward)) * 0.4;
    f.up = cross(f.forward, f.right);
    f.columns = 8;
    f.rows = 6;
    f.du = 0.02;
    f.dv = -0.02;
    f.u0 = -0.05;
    f.v0 = 0.04;
    return f;
}

/// Whether some ray of the tile, through a random point of a random pixel
/// or through one of the tile's corners, meets the box.
bool some_ray_meets(const CameraFrustum& f, const Box3& box, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto meets = [&](double u, double v) {
        return box.clip(Ray{f.origin, f.forward + f.right * u + f.up * v}, 0.0, INFINITY).has_value();
    };
    for (const double cu : {0.0, 1.0})
        for (const double cv : {0.0, 1.0})
            if (meets(f.u0 + cu * f.columns * f.du, f.v0 + cv * f.rows * f.dv)) return true;
    for (int i = 0; i < 400; ++i)
        if (meets(f.u0 + unit(rng) * f.columns * f.du, f.v0 + unit(rng) * f.rows * f.dv)) return true;
    return false;
}

TEST(CameraFrustum, ABoxItMissesMeetsNoRayOfTheTile) {
    const CameraFrustum f = tilted_tile();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> centre(-3.0, 3.0), size(0.01, 0.6);
    int missed = 0, kept_hit = 0;
    for (int i = 0; i < 3000; ++i) {
        // Boxes scattered around the eye and along the view, some behind it.
        const Vec3d c = f.origin + f.forward * (2.0 * centre(rng)) + Vec3d{centre(rng), centre(rng), centre(rng)} * 0.3;
        const Vec3d half{size(rng), size(rng), size(rng)};
        const Box3 box{c - half, c + half};
        const bool hit = some_ray_meets(f, box, rng);
        if (f.misses(box)) {
            ++missed;
            EXPECT_FALSE(hit) << "box " << i;
        } else if (hit) {
            ++kept_hit;
        }
    }
    // The test culls most of what it can: many boxes missed, many kept.
    EXPECT_GT(missed, 1000);
    EXPECT_GT(kept_hit, 50);
}

TEST(CameraFrustum, HoldsTheTilesRaysAndNoOthers) {
    const CameraFrustum f = tilted_tile();
    const CameraFrustum::RayCheck check = f.ray_check().value();
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto through = [&](double u, double v) { return Ray{f.origin, normalize(f.forward + f.right * u + f.up * v)}; };
    const double u1 = f.u0 + f.columns * f.du, v1 = f.v0 + f.rows * f.dv;
    for (int i = 0; i < 1000; ++i) {
        const double a = unit(rng), b = unit(rng);
        EXPECT_TRUE(f.holds(through(f.u0 + a * (u1 - f.u0), f.v0 + b * (v1 - f.v0)), check)) << i;
        // Beside the rectangle by a tenth of a pixel or more, or from another point: not the tile's.
        const double off = 0.1 + 3.0 * unit(rng);
        EXPECT_FALSE(f.holds(through(u1 + off * f.du, f.v0 + b * (v1 - f.v0)), check)) << i;
        EXPECT_FALSE(f.holds(through(f.u0 + a * (u1 - f.u0), f.v0 - off * f.dv), check)) << i;
        Ray moved = through(f.u0 + a * (u1 - f.u0), f.v0 + b * (v1 - f.v0));
        moved.origin.x += 1e-12;
        EXPECT_FALSE(f.holds(moved, check)) << i;
    }
    // The tile's corners are its own; a ray backwards is not.
    EXPECT_TRUE(f.holds(through(f.u0, f.v0), check));
    EXPECT_TRUE(f.holds(through(u1, v1), check));
    EXPECT_FALSE(f.holds(Ray{f.origin, -f.forward}, check));
}

TEST(CameraFrustum, BoxesBehindBesideAndAroundTheEye) {
    const CameraFrustum f = tilted_tile();
    const Vec3d ahead = f.origin + f.forward * 3.0;
    const Vec3d unit{0.1, 0.1, 0.1};
    EXPECT_FALSE(f.misses({ahead - unit, ahead + unit}));                          // on the tile's central ray
    const Vec3d behind = f.origin - f.forward * 3.0;
    EXPECT_TRUE(f.misses({behind - unit, behind + unit}));                         // behind the eye
    const Vec3d beside = ahead + f.right * 5.0;
    EXPECT_TRUE(f.misses({beside - unit, beside + unit}));                         // far to the right
    EXPECT_FALSE(f.misses({f.origin - unit, f.origin + unit}));                    // around the eye
    const Vec3d beside_eye = f.origin + f.right * 5.0;
    EXPECT_TRUE(f.misses({beside_eye - unit, beside_eye + unit}));                 // beside the eye, partly behind it
    constexpr double inf = INFINITY;
    EXPECT_FALSE(f.misses({{-inf, -inf, -inf}, {inf, inf, inf}}));                 // everything
    EXPECT_FALSE(f.misses({{NAN, 0, 0}, {1, 1, 1}}));                              // not a box: never culled
}

// A review's case: with the eye at the origin, a box of one subnormal point
// on a ray of the tile (on its left edge) — the products of the plane test
// underflow, and a tolerance relative to the sizes alone rounds to 0.
TEST(CameraFrustum, ASubnormalBoxOnATilesRayIsNotCulled) {
    CameraFrustum f;
    f.origin = {0, 0, 0};
    f.forward = {0.11152181372875017, 0.29113174319599172, 0.95016061440490851};
    f.right = {0.98428846941506054, -0.16406619212514387, -0.065257134308156273};
    f.up = {0.13689081064559197, 0.94250973082786715, -0.30485457722588677};
    f.u0 = 0.35606240767633879;
    f.v0 = -1.0093599080721614;
    f.du = f.dv = 0.01;
    f.columns = f.rows = 1;
    const Vec3d d{5, -11, 19};
    ASSERT_TRUE(f.holds(Ray{f.origin, d}, f.ray_check().value()));
    const Vec3d q = d * std::numeric_limits<double>::denorm_min();  // on the ray at t = 2⁻¹⁰⁷⁴
    EXPECT_FALSE(f.misses({q, q}));
}

/// The distance from p to the ray's points at t ≥ 0.
double distance_to_ray(const Vec3d& p, const Ray& ray) {
    const double t = std::max(0.0, dot(p - ray.origin, ray.dir) / dot(ray.dir, ray.dir));
    return length(ray.at(t) - p);
}

/// The distance from the segment [a, b] to the ray: convex along the
/// segment, so a ternary search finds its least.
double distance_segment_to_ray(const Vec3d& a, const Vec3d& b, const Ray& ray) {
    double lo = 0.0, hi = 1.0;
    const auto at = [&](double s) { return distance_to_ray(a + (b - a) * s, ray); };
    for (int i = 0; i < 100; ++i) {
        const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
        if (at(m1) < at(m2)) hi = m2;
        else lo = m1;
    }
    return std::min({at(0.0), at(1.0), at(0.5 * (lo + hi))});
}

// distance_outside is a lower bound on how near any ray of the tile comes
// to a point or a segment (rays through random points of every pixel and
// the tile's corners), and not a loose one: for segments well beside the
// tile it is most of the true distance.
TEST(CameraFrustum, NoRayOfTheTileComesNearerASegmentThanItsDistanceOutside) {
    const CameraFrustum f = tilted_tile();
    const CameraFrustum::Planes planes = f.planes(f.dual_basis().value());
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0), centre(-3.0, 3.0), offset(-1.0, 1.0);
    int apart = 0, tight = 0;
    for (int i = 0; i < 600; ++i) {
        const Vec3d a = f.origin + f.forward * (2.0 * centre(rng)) + Vec3d{centre(rng), centre(rng), centre(rng)} * 0.4;
        const Vec3d b = i % 3 == 0 ? a : a + Vec3d{offset(rng), offset(rng), offset(rng)};  // a point, or a segment
        const double bound = f.distance_outside(a, b, planes);
        ASSERT_GE(bound, 0.0);
        double nearest = INFINITY;
        for (const double cu : {0.0, 1.0})
            for (const double cv : {0.0, 1.0}) nearest = std::min(nearest, distance_segment_to_ray(a, b, test::tile_ray(f, cu, cv)));
        for (int k = 0; k < 60; ++k) nearest = std::min(nearest, distance_segment_to_ray(a, b, test::tile_ray(f, unit(rng), unit(rng))));
        EXPECT_LE(bound, nearest * (1.0 + 1e-12)) << "segment " << i;
        if (bound > 0.0) ++apart;
        if (bound > 0.5 * nearest && nearest > 0.1) ++tight;
    }
    EXPECT_GT(apart, 300);
    EXPECT_GT(tight, 200);
}

}  // namespace
}  // namespace zeroset
