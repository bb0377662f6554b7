// Shrinking bounds to the surface (trace/search_region.hpp): the shrunk box
// holds every point where f may be ≤ 0, hugs the surface to the documented
// precision however loose the bounds, and keeps the faces where the bounds
// cut the solid or where f is undefined.
#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/trace/search_region.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();

Expr ball(const Vec3d& c, double r) { return square(x - c.x) + square(y - c.y) + square(z - c.z) - r * r; }
Box3 cube(double half) { return {{-half, -half, -half}, {half, half, half}}; }

/// True when `inner` lies in `outer` grown by `margin` on every side.
bool within(const Box3& inner, const Box3& outer, double margin) {
    for (int a = 0; a < 3; ++a)
        if (inner.lo[a] < outer.lo[a] - margin || inner.hi[a] > outer.hi[a] + margin) return false;
    return true;
}

TEST(SearchRegion, LooseBoundsShrinkToTheSurfaceWhateverTheirSize) {
    const Vec3d c{3, -2, 1};
    const Tape tape(ball(c, 0.5));
    const Box3 sphere_box{c - Vec3d{0.5, 0.5, 0.5}, c + Vec3d{0.5, 0.5, 0.5}};
    for (const double half : {4.0, 1e3, 1e8, 1e12, 1e100, 1e300}) {
        const Box3 shrunk = shrink_to_surface(tape, cube(half));
        EXPECT_TRUE(within(sphere_box, shrunk, 0.0)) << "the sphere stays inside, bounds ±" << half;
        // Each face ends within 1/1024 of the width from the sphere: 2 × 1/1024 of 1 … and a little.
        EXPECT_TRUE(within(shrunk, sphere_box, 0.01)) << "bounds ±" << half << " shrink to within 0.01";
    }
}

TEST(SearchRegion, AFaceThatCutsTheSolidStays) {
    const Tape tape(ball({0, 0, 0}, 2.0));  // the box ±1 lies inside the ball
    const Box3 shrunk = shrink_to_surface(tape, cube(1.0));
    EXPECT_EQ(shrunk.lo, cube(1.0).lo);
    EXPECT_EQ(shrunk.hi, cube(1.0).hi);
    // Half inside: only the faces outside the ball move.
    const Box3 half_in{{-1, -1, -1}, {10, 1, 1}};
    const Box3 cut = shrink_to_surface(tape, half_in);
    EXPECT_EQ(cut.lo, half_in.lo);
    EXPECT_GE(cut.hi.x, 2.0);
    EXPECT_LE(cut.hi.x, 2.0 + 0.02);
}

TEST(SearchRegion, NoSurfaceOrNothingProvenLeavesTheBounds) {
    const Box3 bounds = cube(1.0);
    const Box3 far = shrink_to_surface(Tape(ball({5, 5, 5}, 1.0)), bounds);  // f > 0 all over
    EXPECT_EQ(far.lo, bounds.lo);
    EXPECT_EQ(far.hi, bounds.hi);
    // A gyroid fills its box: interval arithmetic proves no slab clear.
    const Tape gyroid(sin(x) * cos(y) + sin(y) * cos(z) + sin(z) * cos(x));
    const Box3 g = shrink_to_surface(gyroid, cube(10.0));
    EXPECT_TRUE(within(cube(10.0), g, 0.0) && within(g, cube(10.0), 0.0));
}

TEST(SearchRegion, WhereFIsUndefinedTheBoundsStayForTheNanError) {
    // sqrt(x) is NaN for x < 0: that half is not shown to be outside, so the
    // methods still look there and report the NaN.
    const Tape tape(sqrt(x) - 5.0);
    const Box3 shrunk = shrink_to_surface(tape, cube(10.0));
    EXPECT_EQ(shrunk.lo.x, -10.0);
}

TEST(SearchRegion, ProofsSplitTheSideThatTightensThem) {
    // The piriform 4x⁴ − 4x³ + y² + z² (POV-Ray's piriform.pov) reaches
    // |y|, |z| ≤ 0.65 at x = 3/4. A slab such as y ≥ 0.7 across the box is
    // proven outside only where x is split finely (4x⁴ − 4x³ over [0, 1]
    // encloses as [−4, 4]); splitting the slab's widest side, z, left the
    // box at |y|, |z| ≤ 1.49, and choosing the side whose halves enclose
    // highest shrinks it to within 0.2 (0.81 with 16 cells a proof).
    const Tape tape(4.0 * pow(x, 4) - 4.0 * pow(x, 3) + square(y) + square(z));
    const Box3 shrunk = shrink_to_surface(tape, cube(2.0));
    const double reach = std::sqrt(4.0 * (0.75 * 0.75 * 0.75 - 0.75 * 0.75 * 0.75 * 0.75));  // 0.6495…
    const Box3 surface{{0.0, -reach, -reach}, {1.0, reach, reach}};
    EXPECT_TRUE(within(surface, shrunk, 0.0));
    EXPECT_TRUE(within(shrunk, surface, 0.2)) << shrunk.lo.y << " " << shrunk.hi.y << " " << shrunk.lo.z << " "
                                              << shrunk.hi.z << " " << shrunk.lo.x << " " << shrunk.hi.x;
}

TEST(SearchRegion, PassesStopWhenTheyNoLongerHalveTheBox) {
    // grafbic.pov's quartic in ±10⁴: interval bounds creep in on its tail
    // (y < 0) by ~15 % a pass for some 30 passes. Shrinking stops once a
    // pass keeps more than half the volume; the box it stops at still holds
    // all that the full shrink keeps.
    const Tape tape(3.0 * square(y) - 2.0 * square(x) + square(y) * square(x) + pow(x, 4) + 4.0 * square(x) * y +
                    2.0 * square(x) * square(z) + square(y) * square(z) + 4.0 * y * square(z) - 4.0 * y + pow(z, 4) -
                    2.0 * square(z) + 1.0);
    ShrinkLimits every_pass;
    every_pass.max_kept_volume = 1.0;
    const Box3 full = shrink_to_surface(tape, cube(1e4), every_pass);
    const Box3 stopped = shrink_to_surface(tape, cube(1e4));
    ShrinkLimits one_pass;
    one_pass.max_passes = 1;
    const Box3 first = shrink_to_surface(tape, cube(1e4), one_pass);
    EXPECT_TRUE(within(full, stopped, 0.0));
    EXPECT_TRUE(within(stopped, first, 0.0));
    EXPECT_LT(stopped.lo.y, 2.0 * full.lo.y) << "stopped early, with the tail still long";
    EXPECT_GT(stopped.lo.y, 0.5 * first.lo.y) << "but after the passes that shrink fast: " << first.lo.y;
}

TEST(SearchRegion, ClipsToTheShrunkBoxAndASphericalBounds) {
    const Tape tape(ball({0, 0, 0}, 1.0));
    const SearchRegion box_region(tape, Bounds::make_box(cube(1e9)));
    const Ray ray{{-5, 0.5, 0}, {1, 0, 0}};
    const auto span = box_region.clip(ray, 0.0, INFINITY);
    ASSERT_TRUE(span.has_value());
    EXPECT_GT(span->t0, 3.99);
    EXPECT_LT(span->t0, 5.0 - std::sqrt(0.75));
    EXPECT_LT(box_region.scale(), std::sqrt(12.0) * 1.01);
    // Sphere bounds of radius 1.2 around a unit ball: the box shrinks to
    // about ±1; a ray at y = 1.1 is in the sphere but not the box, one at
    // y = z = 0.95 in the box but not the sphere.
    const SearchRegion sphere_region(tape, Bounds::make_sphere({0, 0, 0}, 1.2));
    EXPECT_FALSE(sphere_region.clip({{-5, 1.1, 0.0}, {1, 0, 0}}, 0.0, INFINITY).has_value());
    EXPECT_FALSE(sphere_region.clip({{-5, 0.95, 0.95}, {1, 0, 0}}, 0.0, INFINITY).has_value());
    EXPECT_TRUE(sphere_region.clip({{-5, 0.5, 0.5}, {1, 0, 0}}, 0.0, INFINITY).has_value());
    EXPECT_THROW(SearchRegion(tape, Bounds::none()), std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
