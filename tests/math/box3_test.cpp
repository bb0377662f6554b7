// Box3: geometry helpers and the slab test that clips a ray to the box.
#include "zeroset/math/box3.hpp"

#include <gtest/gtest.h>

#include <random>

namespace zeroset {
namespace {

const Box3 unit{{-1, -1, -1}, {1, 1, 1}};

TEST(Box3, Basics) {
    const Box3 b{{0, 1, 2}, {2, 5, 3}};
    EXPECT_EQ(b.center(), (Vec3d{1, 3, 2.5}));
    EXPECT_EQ(b.size(), (Vec3d{2, 4, 1}));
    EXPECT_DOUBLE_EQ(b.diagonal(), std::sqrt(21.0));
    EXPECT_TRUE(b.contains({0, 1, 2}));
    EXPECT_TRUE(b.contains({2, 5, 3}));
    EXPECT_FALSE(b.contains({2.0001, 3, 2.5}));
    EXPECT_TRUE(b.valid());
    EXPECT_FALSE((Box3{{0, 0, 0}, {1, -1, 1}}).valid());
}

TEST(Box3, ClipThroughTheMiddle) {
    const auto s = unit.clip({{-5, 0, 0}, {1, 0, 0}}, 0.0, 100.0);
    ASSERT_TRUE(s.has_value());
    EXPECT_DOUBLE_EQ(s->t0, 4.0);
    EXPECT_DOUBLE_EQ(s->t1, 6.0);
    // Negative direction: the slab's entry and exit swap.
    const auto r = unit.clip({{0, 5, 0}, {0, -2, 0}}, 0.0, 100.0);
    ASSERT_TRUE(r.has_value());
    EXPECT_DOUBLE_EQ(r->t0, 2.0);
    EXPECT_DOUBLE_EQ(r->t1, 3.0);
}

TEST(Box3, ClipRespectsTheParameterRange) {
    const Ray ray{{-5, 0, 0}, {1, 0, 0}};
    const auto s = unit.clip(ray, 4.5, 5.5);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->t0, 4.5);
    EXPECT_EQ(s->t1, 5.5);
    EXPECT_FALSE(unit.clip(ray, 0.0, 3.9).has_value());
    EXPECT_FALSE(unit.clip(ray, 6.1, 9.0).has_value());
    // Origin inside: the span starts at t_min.
    const auto inside = unit.clip({{0, 0, 0}, {0, 0, 1}}, 0.0, 10.0);
    ASSERT_TRUE(inside.has_value());
    EXPECT_EQ(inside->t0, 0.0);
    EXPECT_DOUBLE_EQ(inside->t1, 1.0);
}

TEST(Box3, ClipMisses) {
    EXPECT_FALSE(unit.clip({{-5, 2, 0}, {1, 0, 0}}, 0.0, 100.0).has_value());     // parallel, outside the y slab
    EXPECT_FALSE(unit.clip({{-5, 0, 0}, {-1, 0, 0}}, 0.0, 100.0).has_value());    // pointing away
    EXPECT_FALSE(unit.clip({{-5, -5, 0}, {1, 0.5, 0}}, 0.0, 100.0).has_value());  // passes beside a corner
    // Parallel ray exactly on a face: touching counts.
    EXPECT_TRUE(unit.clip({{-5, 1, 0}, {1, 0, 0}}, 0.0, 100.0).has_value());
}

TEST(Box3, ClippedSpanIsInsideTheBox) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    int hits = 0, misses = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
        const auto s = unit.clip(ray, 0.0, 10.0);
        // Dense samples along the ray agree with the span about being inside.
        bool any_inside = false;
        for (int k = 0; k <= 1000; ++k) {
            const double t = 10.0 * k / 1000.0;
            const Vec3d p = ray.at(t);
            const bool inside = (Box3{{-1 + 1e-9, -1 + 1e-9, -1 + 1e-9}, {1 - 1e-9, 1 - 1e-9, 1 - 1e-9}}).contains(p);
            any_inside = any_inside || inside;
            if (inside) {
                ASSERT_TRUE(s.has_value()) << "ray " << i << " enters the box at t = " << t;
                ASSERT_GE(t, s->t0 - 1e-12);
                ASSERT_LE(t, s->t1 + 1e-12);
            }
        }
        if (s) {
            ++hits;
            const Vec3d m = ray.at(0.5 * (s->t0 + s->t1));
            EXPECT_TRUE((Box3{{-1 - 1e-12, -1 - 1e-12, -1 - 1e-12}, {1 + 1e-12, 1 + 1e-12, 1 + 1e-12}}).contains(m));
        } else {
            ++misses;
            EXPECT_FALSE(any_inside);
        }
    }
    EXPECT_GT(hits, 100);
    EXPECT_GT(misses, 100);
}

}  // namespace
}  // namespace zeroset
