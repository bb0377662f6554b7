// Bounds: the enclosing box and the ray clip, for boxes and spheres.
#include "zeroset/trace/bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace zeroset {
namespace {

TEST(Bounds, EnclosingBox) {
    const Bounds box = Bounds::make_box({{-1, -2, -3}, {1, 2, 3}});
    EXPECT_EQ(box.enclosing_box().lo, (Vec3d{-1, -2, -3}));
    EXPECT_EQ(box.enclosing_box().hi, (Vec3d{1, 2, 3}));
    const Bounds sphere = Bounds::make_sphere({1, 2, 3}, 0.5);
    EXPECT_EQ(sphere.enclosing_box().lo, (Vec3d{0.5, 1.5, 2.5}));
    EXPECT_EQ(sphere.enclosing_box().hi, (Vec3d{1.5, 2.5, 3.5}));
}

TEST(Bounds, BoxClipIsTheSlabTest) {
    const Bounds b = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
    const auto s = b.clip({{-3, 0.5, 0}, {1, 0, 0}}, 0.0, 10.0);
    ASSERT_TRUE(s.has_value());
    EXPECT_DOUBLE_EQ(s->t0, 2.0);
    EXPECT_DOUBLE_EQ(s->t1, 4.0);
    EXPECT_FALSE(b.clip({{-3, 1.5, 0}, {1, 0, 0}}, 0.0, 10.0).has_value());
}

TEST(Bounds, SphereClip) {
    const Bounds b = Bounds::make_sphere({0, 0, 5}, 2.0);
    // Straight through the centre.
    const auto s = b.clip({{0, 0, 0}, {0, 0, 1}}, 0.0, 100.0);
    ASSERT_TRUE(s.has_value());
    EXPECT_DOUBLE_EQ(s->t0, 3.0);
    EXPECT_DOUBLE_EQ(s->t1, 7.0);
    // The direction need not be normalised: t scales inversely.
    const auto h = b.clip({{0, 0, 0}, {0, 0, 2}}, 0.0, 100.0);
    ASSERT_TRUE(h.has_value());
    EXPECT_DOUBLE_EQ(h->t0, 1.5);
    EXPECT_DOUBLE_EQ(h->t1, 3.5);
    // Going the other way: both roots behind the origin.
    EXPECT_FALSE(b.clip({{0, 0, 0}, {0, 0, -1}}, 0.0, 100.0).has_value());
    // Origin inside: starts at t_min.
    const auto inside = b.clip({{0, 0, 5}, {1, 0, 0}}, 0.0, 100.0);
    ASSERT_TRUE(inside.has_value());
    EXPECT_EQ(inside->t0, 0.0);
    EXPECT_DOUBLE_EQ(inside->t1, 2.0);
    // A miss, a tangent, and a zero direction.
    EXPECT_FALSE(b.clip({{2.1, 0, 0}, {0, 0, 1}}, 0.0, 100.0).has_value());
    const auto tangent = b.clip({{2, 0, 0}, {0, 0, 1}}, 0.0, 100.0);
    ASSERT_TRUE(tangent.has_value());
    EXPECT_NEAR(tangent->t0, 5.0, 1e-7);
    EXPECT_NEAR(tangent->t1, 5.0, 1e-7);
    EXPECT_FALSE(b.clip({{0, 0, 0}, {0, 0, 0}}, 0.0, 100.0).has_value());
    // The parameter range is respected.
    const auto part = b.clip({{0, 0, 0}, {0, 0, 1}}, 4.0, 6.0);
    ASSERT_TRUE(part.has_value());
    EXPECT_EQ(part->t0, 4.0);
    EXPECT_EQ(part->t1, 6.0);
    EXPECT_FALSE(b.clip({{0, 0, 0}, {0, 0, 1}}, 7.5, 9.0).has_value());
}

// Ordinary lengths are clipped without the scaling below, which changes no
// bit: the same rays 2^450 times larger (scaled) give the same spans, 2^450
// times larger, exactly.
TEST(Bounds, SphereClipIsTheSameWithAndWithoutScaling) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    constexpr double big = 0x1p450;
    int met = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3d c{u(random), u(random), u(random)}, o{u(random), u(random), u(random)}, d{u(random), u(random), u(random)};
        const double r = std::abs(u(random)) + 0.1;
        const auto plain = Bounds::make_sphere(c, r).clip({o, d}, -INFINITY, INFINITY);
        const auto scaled = Bounds::make_sphere(c * big, r * big).clip({o * big, d}, -INFINITY, INFINITY);
        ASSERT_EQ(plain.has_value(), scaled.has_value()) << i;
        if (!plain) continue;
        ++met;
        EXPECT_EQ(plain->t0 * big, scaled->t0) << i;
        EXPECT_EQ(plain->t1 * big, scaled->t1) << i;
    }
    EXPECT_GT(met, 200);
}

// Squares of radii and offsets past 10¹⁵⁴ overflow, and below 10⁻¹⁶² vanish:
// the clip works in units where neither happens (a soak run found the span
// of a 10³⁰⁰ sphere was [−∞, NaN], and every ray's point NaN).
TEST(Bounds, SphereClipAtEveryScale) {
    const auto huge = Bounds::make_sphere({0, 0, 0}, 1e300).clip({{0, 1, -4}, {0, 0, 1}}, 0.0, INFINITY);
    ASSERT_TRUE(huge.has_value());
    EXPECT_EQ(huge->t0, 0.0);
    EXPECT_NEAR(huge->t1 / 1e300, 1.0, 1e-15);
    const auto tiny = Bounds::make_sphere({0, 0, 0}, 1e-200).clip({{-3e-200, 0, 0}, {1, 0, 0}}, 0.0, INFINITY);
    ASSERT_TRUE(tiny.has_value());
    EXPECT_NEAR(tiny->t0 / 2e-200, 1.0, 1e-15);
    EXPECT_NEAR(tiny->t1 / 4e-200, 1.0, 1e-15);
    const Bounds unit = Bounds::make_sphere({0, 0, 0}, 1.0);
    const auto slow = unit.clip({{0, 0, -3}, {0, 0, 1e-300}}, 0.0, INFINITY);
    ASSERT_TRUE(slow.has_value());
    EXPECT_NEAR(slow->t0 / 2e300, 1.0, 1e-15);
    EXPECT_NEAR(slow->t1 / 4e300, 1.0, 1e-15);
    const auto fast = unit.clip({{0, 0, -3}, {0, 0, 1e300}}, 0.0, INFINITY);
    ASSERT_TRUE(fast.has_value());
    EXPECT_NEAR(fast->t0 / 2e-300, 1.0, 1e-15);
    EXPECT_FALSE(unit.clip({{0, 2, -3}, {0, 0, 1e-300}}, 0.0, INFINITY).has_value());
}

TEST(Bounds, SphereClipAgreesWithPointSamples) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-4.0, 4.0);
    const Vec3d centre{0.3, -0.2, 0.5};
    const double radius = 1.7;
    const Bounds b = Bounds::make_sphere(centre, radius);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
        const auto s = b.clip(ray, 0.0, 5.0);
        hits += s.has_value();
        for (int k = 0; k <= 500; ++k) {
            const double t = 5.0 * k / 500.0;
            const double d = length(ray.at(t) - centre);
            if (d < radius * (1 - 1e-9)) {
                ASSERT_TRUE(s.has_value()) << "ray " << i << " is inside at t = " << t;
                ASSERT_GE(t, s->t0 - 1e-9);
                ASSERT_LE(t, s->t1 + 1e-9);
            }
        }
        if (s) {
            // The span's ends are on the sphere or at the range's ends.
            for (const double t : {s->t0, s->t1}) {
                const double d = length(ray.at(t) - centre);
                if (t != 0.0 && t != 5.0)
                    EXPECT_NEAR(d, radius, 1e-9 * (1 + length(ray.dir) * 5));
                else
                    EXPECT_LE(d, radius * (1 + 1e-12));
            }
        }
    }
    EXPECT_GT(hits, 100);
}

// A sphere gate's focus is found without the clip's square root: it must
// say the same as the clip-based definition — the ray meets the sphere
// from min(t_min, 0) on, and then its nearest approach to the centre,
// clamped to that part — on rays from inside, outside, grazing and
// pointing away, and at extreme scales, where it takes the clip itself.
TEST(Bounds, SphereGateFocusIsTheClampedNearestApproach) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    const auto reference = [](const Bounds& gate, const Ray& ray, double t_min) -> std::optional<double> {
        const auto in_gate = gate.clip(ray, std::min(t_min, 0.0), INFINITY);
        if (!in_gate) return std::nullopt;
        const double nearest = -dot(ray.origin - gate.center, ray.dir) / dot(ray.dir, ray.dir);
        return std::clamp(nearest, in_gate->t0, in_gate->t1);
    };
    int met = 0, missed = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3d c{u(random), u(random), u(random)}, o{u(random), u(random), u(random)}, d{u(random), u(random), u(random)};
        const Bounds gate = Bounds::make_sphere(c, std::abs(u(random)) + 0.1);
        const double t_min = i % 3 == 0 ? u(random) : 0.0;
        const auto fast = gate_focus(gate, {o, d}, t_min), slow = reference(gate, {o, d}, t_min);
        ASSERT_EQ(fast.has_value(), slow.has_value()) << i;
        if (!fast) {
            ++missed;
            continue;
        }
        ++met;
        EXPECT_NEAR(*fast, *slow, 1e-12 * (1.0 + std::abs(*slow))) << i;
    }
    EXPECT_GT(met, 500);
    EXPECT_GT(missed, 1000);
    // A ray grazing the unit sphere at t = 2, and one whose exit lies behind it.
    const Bounds unit = Bounds::make_sphere({0, 0, 0}, 1.0);
    EXPECT_EQ(gate_focus(unit, {{-2, 1, 0}, {1, 0, 0}}, 0.0), 2.0);
    EXPECT_FALSE(gate_focus(unit, {{2, 0, 0}, {1, 0, 0}}, 0.0).has_value());
    EXPECT_EQ(gate_focus(unit, {{0.5, 0, 0}, {1, 0, 0}}, 0.0), 0.0);  // inside, past the middle: the start
    // Past ordinary sizes the clip's scaled arithmetic answers.
    const auto huge = gate_focus(Bounds::make_sphere({0, 0, 0}, 1e300), {{0, 1, -4e300}, {0, 0, 1}}, 0.0);
    ASSERT_TRUE(huge.has_value());
    EXPECT_NEAR(*huge / 4e300, 1.0, 1e-15);
    // Lengths of 10¹⁰⁰ each are still ordinary one by one, but b² and a·c,
    // products of four, would overflow to a NaN discriminant: a ray pointing
    // away was taken for one that meets the gate.
    const Bounds big = Bounds::make_sphere({0, 0, 0}, 1e100);
    EXPECT_FALSE(gate_focus(big, {{0, 0, -4e100}, {0, 0, -1e100}}, 0.0).has_value());
    const auto towards = gate_focus(big, {{0, 0, -4e100}, {0, 0, 1e100}}, 0.0);
    ASSERT_TRUE(towards.has_value());
    EXPECT_NEAR(*towards, 4.0, 1e-12);
}

// The clip without scaling must keep b² and a·c in range: with a radius,
// an offset and a direction of 10¹⁰⁰ (and of 10⁻¹⁰⁰) they overflowed
// (underflowed) once lengths up to 2^±400 went unscaled.
TEST(Bounds, SphereClipOfLargeAndSmallRaysMeetsTheSphere) {
    for (const double size : {1e100, 1e-100, 1e70, 1e-70}) {
        const auto span = Bounds::make_sphere({0, 0, 0}, size).clip({{0, 0, -4 * size}, {0, 0, size}}, 0.0, INFINITY);
        ASSERT_TRUE(span.has_value()) << size;
        EXPECT_NEAR(span->t0, 3.0, 1e-12) << size;
        EXPECT_NEAR(span->t1, 5.0, 1e-12) << size;
    }
}

}  // namespace
}  // namespace zeroset
