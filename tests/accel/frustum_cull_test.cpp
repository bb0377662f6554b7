// FrustumCuller: no ray of a pixel meets the solid before the pixel's first
// depth (sampled densely along rays through the whole pixel), and the
// culling proves something: rays that miss are culled, rays that hit start
// past the box's front.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "zeroset/accel/frustum_cull.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

Expr ball(const Vec3d& c, double r) {
    return sqrt(square(var_x() - c.x) + square(var_y() - c.y) + square(var_z() - c.z)) - r;
}

/// A tile of 16 × 12 pixels looking along +z from z = −5 at three balls.
CameraFrustum tile() {
    CameraFrustum f;
    f.origin = {0.1, 0.05, -5};
    f.forward = {0, 0, 1};
    f.right = {1, 0, 0};
    f.up = {0, 1, 0};
    f.columns = 16;
    f.rows = 12;
    f.du = 0.6 / f.columns;
    f.dv = -0.45 / f.rows;
    f.u0 = -0.3;
    f.v0 = 0.225;
    return f;
}

TEST(FrustumCuller, NoRayOfAPixelMeetsTheSolidBeforeItsFirstDepth) {
    const Expr f = min(min(ball({-0.7, 0.3, 0.2}, 0.5), ball({0.6, -0.2, -0.4}, 0.35)), ball({0.2, 0.6, 0.9}, 0.15));
    const Tape tape(f);
    Evaluator<double> value(tape);
    const Box3 box{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};
    const CameraFrustum frustum = tile();
    FrustumCuller culler(tape);
    TraceCounters counters;
    std::vector<double> first_depth;
    culler.cull(frustum, box, first_depth, counters);
    EXPECT_GT(counters.interval_evaluations, 0u);

    int culled = 0, hits = 0, hits_moved_in = 0;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int j = 0; j < frustum.rows; ++j)
        for (int i = 0; i < frustum.columns; ++i) {
            const int pixel = j * frustum.columns + i;
            const double depth = first_depth[static_cast<std::size_t>(pixel)];
            if (depth == inf) ++culled;
            bool centre_hits = false;
            // Rays through the pixel's centre and near its corners.
            for (const auto& [a, b] : {std::pair{0.5, 0.5}, {0.0, 0.0}, {0.999, 0.0}, {0.0, 0.999}, {0.999, 0.999}}) {
                const double u = frustum.u0 + (i + a) * frustum.du, v = frustum.v0 + (j + b) * frustum.dv;
                const Ray ray{frustum.origin, normalize(frustum.forward + frustum.right * u + frustum.up * v)};
                const auto span = box.clip(ray, 0.0, inf);
                if (!span) continue;
                const double t_first = depth == inf ? inf : depth / frustum.depth_rate(ray.dir);
                constexpr int samples = 4000;
                for (int k = 0; k <= samples; ++k) {
                    const double t = span->t0 + (span->t1 - span->t0) * k / samples;
                    const Vec3d p = ray.at(t);
                    const bool inside = value(p.x, p.y, p.z) <= 0.0;
                    if (inside && a == 0.5) centre_hits = true;
                    if (t < t_first) {
                        ASSERT_FALSE(inside) << "pixel (" << i << ", " << j << ") at t = " << t;
                    }
                }
            }
            if (centre_hits) {
                ++hits;
                if (depth > frustum.depth_of(box.lo) + 0.5) ++hits_moved_in;
            }
        }
    // Some pixels see the balls, some see nothing: each kind is culled.
    EXPECT_GT(hits, 20);
    EXPECT_GT(culled, 40);
    EXPECT_EQ(hits_moved_in, hits);  // every hit starts at least half a unit past the box's front face
}

TEST(FrustumCuller, ABoxBehindTheEyeCullsEveryPixel) {
    const Tape tape(ball({0, 0, -9}, 0.5));
    FrustumCuller culler(tape);
    TraceCounters counters;
    std::vector<double> first_depth;
    culler.cull(tile(), {{-1, -1, -10}, {1, 1, -8}}, first_depth, counters);
    ASSERT_EQ(first_depth.size(), static_cast<std::size_t>(tile().pixels()));
    for (const double depth : first_depth) EXPECT_EQ(depth, std::numeric_limits<double>::infinity());
}

TEST(FrustumCuller, AnEyeInsideTheSolidStartsAtOnce) {
    const Tape tape(ball({0, 0, -5}, 1.0));  // the eye at (0.1, 0.05, −5) is inside
    FrustumCuller culler(tape);
    TraceCounters counters;
    std::vector<double> first_depth;
    culler.cull(tile(), {{-2, -2, -7}, {2, 2, -3}}, first_depth, counters);
    ASSERT_EQ(first_depth.size(), static_cast<std::size_t>(tile().pixels()));
    for (const double depth : first_depth) EXPECT_EQ(depth, 0.0);
}

TEST(CulledTiles, ATileIsCulledOnceForAllItsRays) {
    const Tape tape(ball({0, 0, 0}, 0.5));
    CulledTiles tiles(tape);
    TraceCounters counters;
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    const std::vector<double>* first = tiles.first_depths(tile(), box, counters);
    ASSERT_NE(first, nullptr);
    const std::uint64_t spent = counters.interval_evaluations;
    EXPECT_GT(spent, 0u);
    for (int ray = 0; ray < 100; ++ray) EXPECT_EQ(tiles.first_depths(tile(), box, counters), first);
    EXPECT_EQ(counters.interval_evaluations, spent);  // no culling again
}

TEST(CulledTiles, CullingStopsWhenEachTileServesFewRays) {
    const Tape tape(ball({0, 0, 0}, 0.5));
    CulledTiles tiles(tape);
    TraceCounters counters;
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    // Tiles (here: the same rays seen from eyes moved a little) that each
    // serve one ray: after 32 cullings, no more.
    int culled = 0;
    for (int k = 0; k < 40; ++k) {
        CameraFrustum moved = tile();
        moved.origin.x += 1e-3 * k;
        if (tiles.first_depths(moved, box, counters)) ++culled;
    }
    EXPECT_EQ(culled, 32);
}

}  // namespace
}  // namespace zeroset
