// The blob's cylinder components (accel/blob.hpp): the kernel of the
// distance to a segment, the end planes counted once, and the tube about
// the axis that lets a ray skip the round ends it cannot meet.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

TEST(Blob, ACylinderIsTheKernelOfTheDistanceToItsSegment) {
    // POV-Ray's kernel, strength 2, threshold 1: the surface is where the
    // distance d to the segment has (1 − d²/R²)² = 1/2.
    BlobComponent c;
    c.center = {0, 0, -1};
    c.end = Vec3d{0, 0, 1};
    c.radius = 1.0;
    c.strength = 2.0;
    const auto model = std::make_shared<const BlobModel>(BlobKernel::PovRay, 1.0, std::vector{c});
    const Blob blob(BlobDescription{"tube", model, no_material, 1e-9, 1});
    const double d = std::sqrt(1.0 - std::sqrt(0.5));
    TraceScratch scratch(1);
    // Across the body, along the axis (the body's u constant on the ray),
    // into a round end, and slantwise through all three parts.
    const auto t_of = [&](const Ray& ray) { return blob.first_hit(ray, 0.0, 1e9, scratch).value().t; };
    EXPECT_NEAR(t_of({{-5, 0, 0.3}, {1, 0, 0}}), 5.0 - d, 1e-12);
    EXPECT_NEAR(t_of({{0.2, 0, -5}, {0, 0, 1}}), 4.0 - std::sqrt(d * d - 0.04), 1e-12);
    EXPECT_NEAR(t_of({{0, 0, 5}, {0, 0, -1}}), 4.0 - d, 1e-12);
    const Vec3d slant = normalize(Vec3d{0.3, 0.1, 1.0});
    const Ray through{Vec3d{0.05, 0.02, 0} - 4.0 * slant, slant};
    const double t = t_of(through);
    const Vec3d p = through.at(t);
    EXPECT_NEAR(model->u_at(0, p), 1.0 - std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(blob.value_at(p), 0.0, 1e-12);
    // The normal: away from the nearest point of the segment.
    const Vec3d side{-5, 0, 0.3};
    const auto hit = blob.first_hit({side, {1, 0, 0}}, 0.0, 1e9, scratch).value();
    const Vec3d n = blob.local_normal(hit.surface, scratch);
    EXPECT_NEAR(n.x, -1.0, 1e-12);
    EXPECT_NEAR(n.z, 0.0, 1e-12);
}

TEST(Blob, ARayInACylindersEndPlaneCountsItOnce) {
    // In the plane through an end, the round end and the body agree: the
    // ray must see one of them, not both (found in review: twice the field).
    BlobComponent c;
    c.center = {0, 0, 0};
    c.end = Vec3d{0, 0, 1};
    c.radius = 1.0;
    const auto model = std::make_shared<const BlobModel>(BlobKernel::PovRay, 0.5, std::vector{c});
    const Blob blob(BlobDescription{"stick", model, no_material, 1e-9, 1});
    TraceScratch scratch(1);
    const double d = std::sqrt(1.0 - std::sqrt(0.5));  // (1 − d²)² = 1/2
    for (const double z : {0.0, 1.0}) {
        const auto hit = blob.first_hit({{-5, 0, z}, {1, 0, 0}}, 0.0, 1e9, scratch);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, 5.0 - d, 1e-12) << z;
        EXPECT_FALSE(blob.first_hit({{-5, 0.6, z}, {1, 0, 0}}, 0.0, 1e9, scratch)) << z;  // K(0.36) < 1/2
    }
    // Starting on the end plane, outside the surface, and leaving it: no hit at the start.
    const double s = std::sqrt(0.5);
    EXPECT_FALSE(blob.first_hit({{0.6, 0, 0}, {s, 0, s}}, 0.0, 1e9, scratch));
    EXPECT_FALSE(blob.first_hit({{0.6, 0, 1}, {s, 0, -s}}, 0.0, 1e9, scratch));
}

// The tube about a cylinder's axis (Blob::tube_on_ray, which lets a ray skip
// the round ends it cannot meet) holds every t at which any ray within the
// stated rounding of the mapped one comes within reach of the axis line —
// however far along the axis the ray passes (its errors grow with that) and
// however nearly it runs along the axis (then its piece in the tube is long,
// and the errors at the piece's ends are what count).
TEST(Blob, TheTubeHoldsEveryRayWithinTheMappingsRounding) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    const auto random_vector = [&](double size) { return Vec3d{unit(rng), unit(rng), unit(rng)} * size; };
    const auto largest = [](const Vec3d& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); };
    const auto sign = [&] { return fraction(rng) < 0.5 ? -1.0L : 1.0L; };
    constexpr double u = std::numeric_limits<double>::epsilon();
    int pieces = 0;  // rays in reach of the axis, checked against a decided tube
    for (int n = 0; n < 20000; ++n) {
        const double reach = 0.2 + 4.0 * fraction(rng);
        const Vec3d qd = random_vector(std::pow(10.0, -4.0 + 6.0 * fraction(rng)));
        // The nearest approach within a few radii of the axis, at t up to 10⁸.
        const Vec3d q0 = random_vector(2.0) - qd * (std::pow(10.0, 8.0 * fraction(rng)) * unit(rng));
        // The errors as the mapping makes them: in units of the ray's and the
        // axis's sizes, which may far exceed q's own (a ray nearly along the
        // axis, or passing far from the cylinder's centre).
        const Blob::MappedRay across{q0, qd, std::pow(10.0, 14.0 * fraction(rng)) * u * std::max(largest(q0), 1.0),
                                     std::pow(10.0, 14.0 * fraction(rng)) * u * largest(qd)};
        const std::optional<Span> tube = Blob::tube_on_ray(across, reach);
        const bool decided = !tube || std::isfinite(tube->t0);
        for (int trial = 0; trial < 16 && decided; ++trial) {
            // A ray at a corner of the rounding's box, in long double.
            std::array<long double, 3> p{}, d{};
            for (int k = 0; k < 3; ++k) {
                p[k] = static_cast<long double>(q0[k]) + sign() * across.q0_error;
                d[k] = static_cast<long double>(qd[k]) + sign() * across.qd_error;
            }
            const long double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            const long double nearest = -(p[0] * d[0] + p[1] * d[1] + p[2] * d[2]) / dd;
            long double closest = 0.0L;
            for (int k = 0; k < 3; ++k) closest += (p[k] + nearest * d[k]) * (p[k] + nearest * d[k]);
            if (closest > reach) continue;  // this ray never comes within reach
            const long double half = std::sqrt((reach - closest) / dd);
            ASSERT_TRUE(tube) << n << ": the ray comes within reach of the axis at t = " << static_cast<double>(nearest);
            EXPECT_LE(tube->t0, nearest - half) << n;
            EXPECT_GE(tube->t1, nearest + half) << n;
            ++pieces;
        }
    }
    EXPECT_GT(pieces, 50000);  // most cases are decided and in reach, not waved through
}

// The division-free test that a ray passes a cylinder's axis line beside
// its reach (Blob::passes_beside_axis) rejects only rays that are farther
// than the radius from the line through the segment's exact ends — the
// axis it is given is end − centre rounded — by the distance worked out in
// long double: from rays nearly along the line to rays far from the
// segment's start, at every scale from 10⁻²⁰⁰ to 10²⁰⁰ (where squares
// would underflow or overflow, it does not decide). At ordinary scales it
// rejects nearly every ray that is farther by twice its margin.
TEST(Blob, TheAxisTestRejectsOnlyRaysBesideTheTube) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    const auto random_vector = [&](double size) { return Vec3d{unit(rng), unit(rng), unit(rng)} * size; };
    int rejected = 0, clearly_beside = 0, clearly_beside_rejected = 0;
    for (int n = 0; n < 200000; ++n) {
        const bool ordinary = fraction(rng) < 0.8;
        const double scale = ordinary ? 1.0 : std::pow(10.0, -200.0 + 400.0 * fraction(rng));
        const double size = scale * std::pow(10.0, -3.0 + 6.0 * fraction(rng));
        const Vec3d center = random_vector(size * std::pow(10.0, 4.0 * fraction(rng)));
        // An end far from the centre one time in four (its rounded axis then
        // misses the exact end by a unit of the axis's length).
        const Vec3d end = center + random_vector(fraction(rng) < 0.25 ? size * 1e6 : size);
        const Vec3d direction = end - center;
        const double radius = size * (0.1 + fraction(rng));
        // A direction near the line's about one time in four, within 10⁻¹⁰ to 1 radian.
        Vec3d dir = random_vector(scale);
        if (fraction(rng) < 0.25) dir = direction + random_vector(length(direction) * std::pow(10.0, -10.0 * fraction(rng)));
        // Passing the line at up to twice the radius, near either end or far along it.
        const Vec3d near_line = fraction(rng) < 0.5 ? end : center + direction * (100.0 * unit(rng));
        const Vec3d origin =
            near_line + random_vector(2.0 * radius) - dir * (std::pow(10.0, 6.0 * fraction(rng)) * unit(rng) / length(dir) * size);
        const Ray ray{origin, dir};
        const bool beside = Blob::passes_beside_axis(ray, length(origin), length(dir),
                                                     {center, direction, length(center), length(direction)}, radius);
        // The distance between the ray's line and the line through the exact
        // ends, |e·(d × w)|/|d × w|, in long double.
        std::array<long double, 3> e{}, d{}, w{};
        for (int k = 0; k < 3; ++k) {
            e[k] = static_cast<long double>(origin[k]) - static_cast<long double>(center[k]);
            d[k] = dir[k];
            w[k] = static_cast<long double>(end[k]) - static_cast<long double>(center[k]);
        }
        const std::array<long double, 3> normal{d[1] * w[2] - d[2] * w[1], d[2] * w[0] - d[0] * w[2],
                                                d[0] * w[1] - d[1] * w[0]};
        const long double normal_length =
            std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        const long double distance = std::abs(e[0] * normal[0] + e[1] * normal[1] + e[2] * normal[2]) / normal_length;
        if (beside) {
            ++rejected;
            ASSERT_GT(distance, radius) << n;
        }
        const long double sine = normal_length / (length(dir) * std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        const double margin = 2e-8 * (radius + length(origin) + length(center) + length(direction));  // twice the test's own
        if (ordinary && distance > radius + margin && sine > 1e-5L) {
            ++clearly_beside;
            clearly_beside_rejected += beside;
        }
    }
    EXPECT_GT(rejected, 20000);
    EXPECT_GT(clearly_beside_rejected, 0.999 * clearly_beside);
}

// The same test on rays that pass the segment's end: grazing its reach by a
// part in 10³ to 10¹² either way at ordinary sizes (most of those a little
// beyond are turned away), and within or beyond a thin cylinder's reach
// whose radius squared underflows beside an axis of ordinary length (none
// may be turned away wrongly: there the test does not decide).
TEST(Blob, TheAxisTestKeepsRaysGrazingTheReachAtAnyScale) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    const auto random_vector = [&](double size) { return Vec3d{unit(rng), unit(rng), unit(rng)} * size; };
    int ordinary_rejected = 0;
    for (int n = 0; n < 100000; ++n) {
        const bool tiny = n % 2 == 1;
        const double radius = tiny ? std::pow(10.0, -166.0 + 8.0 * fraction(rng)) : 0.5 + fraction(rng);
        const Vec3d center = random_vector(tiny ? radius : 1.0);
        const Vec3d end = center + random_vector(10.0);
        const Vec3d direction = end - center;
        // Across the axis at the end, at the radius give or take a part in 10³ to 10¹².
        const Vec3d across = normalize(cross(direction, random_vector(1.0)));
        const double off = tiny ? radius * (0.2 + 2.0 * fraction(rng))
                                : radius * (1.0 + unit(rng) * std::pow(10.0, -3.0 - 9.0 * fraction(rng)));
        const Vec3d target = end + across * off;
        const Vec3d dir = normalize(cross(across, random_vector(1.0)));  // across the offset: nearest at the target
        const Ray ray{target - dir * (tiny ? 3.0 * radius : 3.0), dir};
        if (!Blob::passes_beside_axis(ray, length(ray.origin), length(dir),
                                      {center, direction, length(center), length(direction)}, radius))
            continue;
        ordinary_rejected += !tiny;
        // Turned away: the ray passes the exact end farther than the radius (in long double).
        long double dd = 0, ed = 0, ee = 0;
        for (int k = 0; k < 3; ++k) {
            const long double e = static_cast<long double>(ray.origin[k]) - static_cast<long double>(end[k]);
            dd += static_cast<long double>(dir[k]) * dir[k];
            ed += e * dir[k];
            ee += e * e;
        }
        ASSERT_GT(ee - ed * ed / dd, static_cast<long double>(radius) * radius) << n << (tiny ? " (tiny)" : "");
    }
    EXPECT_GT(ordinary_rejected, 5000);
}

// An axis so short that 1/|w|² overflows (|w|² below 2⁻¹⁰²⁴) is divided
// by, not multiplied by its inverse: ∞ made the ray's place along it NaN
// and dropped every part (found in review). The component is then a ball.
TEST(Blob, ACylinderWithAVanishingAxisStillCounts) {
    BlobComponent c;
    c.center = {0, 0, 0};
    c.end = Vec3d{1e-155, 0, 0};
    c.radius = 1.0;
    const auto model = std::make_shared<const BlobModel>(BlobKernel::PovRay, 0.5, std::vector{c});
    const Blob blob(BlobDescription{"dot", model, no_material, 1e-9, 1});
    TraceScratch scratch(1);
    const double d2 = 1.0 - std::sqrt(0.5);  // (1 − d²)² = 1/2
    for (const Vec3d& dir : {Vec3d{1, 0, 0}, Vec3d{1, 1e-3, 0}, Vec3d{1, 0, 1e-3}}) {
        const Ray ray{{-5, 0.1, 0}, dir};
        const auto hit = blob.first_hit(ray, 0.0, 1e9, scratch);
        ASSERT_TRUE(hit) << dir.y << " " << dir.z;
        EXPECT_NEAR(dot(ray.at(hit->t), ray.at(hit->t)), d2, 1e-9);
    }
}

}  // namespace
}  // namespace zeroset
