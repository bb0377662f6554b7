// Deformations at the function level (expr/deform.hpp): each forward map D
// and its closed-form inverse undo each other at random points (the same
// inverse that builds f∘D⁻¹), the deformed function vanishes on the deformed
// surface, its Dual gradient agrees with central differences, affine maps
// agree with their matrices, and bad parameters are refused.
#include "zeroset/expr/deform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

struct Sampler {
    std::mt19937_64 rng{11};
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    Vec3d point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
    Vec3d direction() { return normalize(Vec3d{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}); }
};

testing::AssertionResult same_point(const Vec3d& a, const Vec3d& b, double tolerance) {
    if (length(a - b) <= tolerance) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y
                                       << ", " << b.z << ")";
}

TEST(Deform, TaperAndTwistInvertAtRandomPoints) {
    Sampler s;
    for (int n = 0; n < 400; ++n) {
        const Vec3d axis = n % 4 == 0 ? Vec3d{0, 0, 1} : s.direction();
        const Vec3d p = s.point(2.0);
        const Taper taper(axis, s.uniform(-0.4, 0.4));  // r = 1 + rate·h > 0.1 for |h| ≤ 2√3
        const Twist twist(axis, s.uniform(-3, 3));
        EXPECT_TRUE(same_point(taper.forward(taper.inverse(p)), p, 1e-13));
        EXPECT_TRUE(same_point(taper.inverse(taper.forward(p)), p, 1e-13));
        EXPECT_TRUE(same_point(twist.forward(twist.inverse(p)), p, 1e-13));
        EXPECT_TRUE(same_point(twist.inverse(twist.forward(p)), p, 1e-13));
        // A twist is a rotation about the axis: it keeps h and the distance to the axis.
        const Vec3d q = twist.forward(p);
        EXPECT_NEAR(dot(q, normalize(axis)), dot(p, normalize(axis)), 1e-14);
        EXPECT_NEAR(length(q), length(p), 1e-13);
    }
}

TEST(Deform, BendInvertsAtRandomPoints) {
    Sampler s;
    int outside_region = 0;
    for (int n = 0; n < 2000; ++n) {
        const bool aligned = n % 3 == 0;
        const Vec3d along = aligned ? Vec3d{0, 1, 0} : s.direction();
        const Vec3d toward = aligned ? Vec3d{1, 0, 0} : s.direction();
        const double rate = s.uniform(-0.8, 0.8);
        // Half the bends limited to a region around 0 of at most a quarter turn each way.
        const double limit = std::numbers::pi / 2 / std::max(std::abs(rate), 1e-3);
        const double lo = n % 2 ? -s.uniform(0, std::min(2.0, limit)) : -Bend::unlimited;
        const double hi = n % 2 ? s.uniform(0, std::min(2.0, limit)) : Bend::unlimited;
        const Bend b(along, toward, rate, lo, hi);
        const Vec3d p = s.point(1.5);
        const double u = dot(p, b.frame.e[0]), v = dot(p, b.frame.e[1]);
        if (!(1.0 - rate * v > 0.05)) continue;  // beyond the centre of curvature: not invertible
        if (u < lo || u > hi) ++outside_region;
        const double tolerance = 1e-12 * (1.0 + std::abs(u) + std::abs(v));
        const std::string what =
            "rate " + std::to_string(rate) + " [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        EXPECT_TRUE(same_point(b.inverse(b.forward(p)), p, tolerance)) << what;
        EXPECT_TRUE(same_point(b.forward(b.inverse(p)), p, tolerance)) << what;
    }
    EXPECT_GT(outside_region, 200);  // the straight continuation is exercised
}

TEST(Deform, BendWindsTheAxisOntoAnArc) {
    // along y, toward x, curvature 0.5: the y axis becomes the circle of radius 2 about (2, 0, 0).
    const Bend arc({0, 1, 0}, {1, 0, 0}, 0.5);
    for (const double h : {-2.0, -0.5, 0.0, 1.0, 3.0}) {
        const Vec3d q = arc.forward({0, h, 0});
        EXPECT_NEAR(length(q - Vec3d{2, 0, 0}), 2.0, 1e-14) << h;
        EXPECT_NEAR(q.z, 0.0, 1e-15);
        EXPECT_NEAR(std::atan2(q.y, 2.0 - q.x), 0.5 * h, 1e-14);  // arc length h
    }
    // Limited to 0 ≤ y ≤ 1: below, nothing moves; above, a straight continuation of the arc's end.
    const Bend part({0, 1, 0}, {1, 0, 0}, 0.5, 0.0, 1.0);
    EXPECT_TRUE(same_point(part.forward({0.3, -1.0, 0.2}), {0.3, -1.0, 0.2}, 1e-15));
    const Vec3d end = part.forward({0, 1, 0}), beyond = part.forward({0, 2, 0});
    EXPECT_TRUE(same_point(beyond - end, Vec3d{std::sin(0.5), std::cos(0.5), 0}, 1e-14));
    // Rate 0 is the identity, and a tiny rate stays accurate (no 1/rate cancellation).
    EXPECT_EQ(bend(Y, Bend({0, 1, 0}, {1, 0, 0}, 0.0)), Y);
    const Bend tiny({0, 1, 0}, {1, 0, 0}, 1e-9);
    const Vec3d p{0.7, 1.3, -0.4};
    EXPECT_TRUE(same_point(tiny.inverse(tiny.forward(p)), p, 1e-15));
    EXPECT_TRUE(same_point(tiny.forward(p), p, 2e-9));
}

double value(const Expr& f, const Vec3d& p) {
    const Tape tape(f);
    Evaluator<double> eval(tape);
    return eval(p.x, p.y, p.z);
}

/// A point on the surface of the box |x| ≤ 0.5, |y| ≤ 0.3, |z| ≤ 1.
Vec3d on_box(Sampler& s) {
    Vec3d p{s.uniform(-0.5, 0.5), s.uniform(-0.3, 0.3), s.uniform(-1, 1)};
    const int face = static_cast<int>(s.uniform(0, 6));
    const double half[] = {0.5, 0.3, 1.0};
    p[face / 2] = face % 2 ? half[face / 2] : -half[face / 2];
    return p;
}

// f∘D⁻¹ is zero exactly where D put f's surface, and negative where D put f's inside.
TEST(Deform, TheZeroSetIsTheDeformedSurface) {
    const Expr box = max(max(abs(X) - 0.5, abs(Y) - 0.3), abs(Z) - 1.0);
    const Twist twist_z({0, 0, 1}, 0.9);
    const Taper taper_z({0, 0, 1}, 0.3);
    const Bend bend_z({0, 0, 1}, {1, 1, 0}, 0.4, -0.5, 0.8);
    const Twist twist_any({1, 2, -1}, 0.6);
    const std::vector<std::pair<Expr, std::function<Vec3d(const Vec3d&)>>> deformed = {
        {twist(box, twist_z), [&](const Vec3d& p) { return twist_z.forward(p); }},
        {taper(box, taper_z), [&](const Vec3d& p) { return taper_z.forward(p); }},
        {bend(box, bend_z), [&](const Vec3d& p) { return bend_z.forward(p); }},
        {twist(box, twist_any), [&](const Vec3d& p) { return twist_any.forward(p); }},
    };
    Sampler s;
    for (const auto& [g, forward] : deformed) {
        const Tape tape(g);
        Evaluator<double> eval(tape);
        for (int n = 0; n < 300; ++n) {
            const Vec3d q = forward(on_box(s));
            EXPECT_NEAR(eval(q.x, q.y, q.z), 0.0, 1e-12);
            const Vec3d inside = forward({s.uniform(-0.45, 0.45), s.uniform(-0.25, 0.25), s.uniform(-0.9, 0.9)});
            EXPECT_LT(eval(inside.x, inside.y, inside.z), 0.0);
        }
    }
}

TEST(Deform, GradientsMatchCentralDifferences) {
    const Expr ellipsoid = square(X) + 2.0 * square(Y) + 3.0 * square(Z) - 1.0;
    const std::vector<Expr> deformed = {
        taper(ellipsoid, Taper({0.2, 1, 0.1}, 0.3)),
        twist(ellipsoid, Twist({0, 0, 1}, 1.3)),
        bend(ellipsoid, Bend({0, 1, 0}, {1, 0, 0}, 0.5)),
        bend(ellipsoid, Bend({1, 1, 1}, {0, 0, 1}, -0.3, -0.4, 0.6)),
        rotate_degrees(translate(ellipsoid, {0.1, -0.2, 0.3}), {20, -35, 50}),
        scale(ellipsoid, {1.5, 0.5, -2.0}),
    };
    Sampler s;
    for (const Expr& g : deformed) {
        const Tape tape(g);
        Evaluator<double> eval(tape);
        Evaluator<Dual<double>> grad(tape);
        for (int n = 0; n < 200; ++n) {
            const Vec3d p = s.point(1.2);
            const Dual<double> d = evaluate_gradient(grad, p);
            ASSERT_DOUBLE_EQ(d.v, eval(p.x, p.y, p.z));
            for (int axis = 0; axis < 3; ++axis) {
                const double h = 1e-6;
                Vec3d a = p, b = p;
                a[axis] += h;
                b[axis] -= h;
                const double fd = (eval(a.x, a.y, a.z) - eval(b.x, b.y, b.z)) / (2 * h);
                EXPECT_NEAR(d.g[axis], fd, 1e-6 * (1 + std::abs(fd))) << g.node_count() << " axis " << axis;
            }
        }
    }
}

TEST(Deform, AffineMapsAgreeWithTheirMatrices) {
    const Expr f = square(X - 0.3) + sin(2.0 * Y) * Z + 0.1 * X * Y;
    const Vec3d angles{30, -45, 60};
    const double radians = std::numbers::pi / 180;
    const Mat4 d = Mat4::rotate({0, 0, 1}, angles.z * radians) * Mat4::rotate({0, 1, 0}, angles.y * radians) *
                   Mat4::rotate({1, 0, 0}, angles.x * radians);
    const Mat4 about = Mat4::rotate({1, 2, 2}, 40 * radians);
    Sampler s;
    for (int n = 0; n < 100; ++n) {
        const Vec3d q = s.point(2.0);
        const double at_q = value(f, q);
        EXPECT_NEAR(value(rotate_degrees(f, angles), d.transform_point(q)), at_q, 1e-12);
        EXPECT_NEAR(value(rotate_about(f, {1, 2, 2}, 40), about.transform_point(q)), at_q, 1e-12);
        EXPECT_NEAR(value(translate(f, {1, -2, 0.5}), q + Vec3d{1, -2, 0.5}), at_q, 1e-12);
        EXPECT_NEAR(value(transform(f, *d.inverse()), d.transform_point(q)), at_q, 1e-12);
        EXPECT_NEAR(value(scale(f, {2, -1, 0.5}), hadamard(q, Vec3d{2, -1, 0.5})), at_q, 1e-12);
        // A uniform scale keeps a distance exact: the unit sphere's distance, scaled by 3.
        EXPECT_NEAR(value(scale(sqrt(square(X) + square(Y) + square(Z)) - 1.0, 3.0), q), length(q) - 3.0, 1e-14);
    }
    // Quarter turns are exact: rotating the function x by 90° about z gives y itself.
    EXPECT_EQ(rotate_about(X, {0, 0, 1}, 90), Y);
    EXPECT_EQ(rotate_degrees(X, {0, 0, 90}), Y);
    EXPECT_EQ(rotate_degrees(Z, {90, 0, 0}), -Y);  // a quarter turn about x takes the planes z = c to y = −c
}

TEST(Deform, BadParametersAreRefused) {
    EXPECT_THROW(Twist({0, 0, 0}, 1.0), std::invalid_argument);
    EXPECT_THROW(Taper({0, 1, 0}, std::nan("")), std::invalid_argument);
    EXPECT_THROW(Bend({0, 1, 0}, {0, 2, 0}, 0.5), std::invalid_argument);  // parallel
    EXPECT_THROW(Bend({0, 1, 0}, {1, 0, 0}, 0.5, 1.0, -1.0), std::invalid_argument);
    EXPECT_THROW(scale(X, 0.0), std::invalid_argument);
    EXPECT_THROW(scale(X, -2.0), std::invalid_argument);
    EXPECT_THROW(scale(X, {1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(rotate_about(X, {0, 0, 0}, 30), std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
