// Issue 9, defect 1: loose but valid bounds must not change what a ray hits.
// A ball of radius 0.5 in bounds from ±4 to ±1e300: every guaranteed method
// finds the same first hit on a ray through it and none on a ray past it.
// (Before the bounds were shrunk to the surface, tolerances scaled with the
// bounds: the polynomial method hit every ray from ±1e8, sphere tracing lost
// the ball from ±1e6, interval and LG from ±1e12.)
#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

const Vec3d centre{3, -2, 1};

ImplicitLeaf ball_in(double half, Method method) {
    const Expr x = var_x() - centre.x, y = var_y() - centre.y, z = var_z() - centre.z;
    LeafDescription d;
    d.name = "ball";
    d.surface = square(x) + square(y) + square(z) - 0.25;
    d.bounds = Bounds::make_box({{-half, -half, -half}, {half, half, half}});
    d.method = method;
    return {0, d};
}

TEST(LooseBounds, EveryGuaranteedMethodHitsTheSameWhateverTheBoundsSize) {
    // Along x at height 0.3 above the centre: enters at x = 3 − 0.4.
    const Ray through{centre + Vec3d{-5, 0.3, 0}, {1, 0, 0}};
    const Ray past{centre + Vec3d{-5, 0.6, 0}, {1, 0, 0}};
    for (const Method method : {Method::Auto, Method::Polynomial, Method::Sphere, Method::Interval, Method::Lg}) {
        for (const double half : {4.0, 1e4, 1e6, 1e8, 1e9, 1e12, 1e100, 1e300}) {
            const ImplicitLeaf leaf = ball_in(half, method);
            TraceScratch scratch(1);
            const auto hit = leaf.first_hit(through, 0.0, INFINITY, scratch);
            ASSERT_TRUE(hit.has_value()) << method_name(method) << ", bounds ±" << half;
            EXPECT_NEAR(hit->t, 5.0 - 0.4, 1e-9) << method_name(method) << ", bounds ±" << half;
            EXPECT_EQ(hit->surface.kind, BoundaryKind::Surface);
            const auto miss = leaf.first_hit(past, 0.0, INFINITY, scratch);
            EXPECT_FALSE(miss.has_value()) << method_name(method) << ", bounds ±" << half << ": hit at "
                                           << (miss ? miss->t : NAN);
            EXPECT_EQ(scratch.counters.failed_queries, 0u);
        }
    }
}

}  // namespace
}  // namespace zeroset
