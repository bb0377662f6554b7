// The distance primitives of expr/shapes.hpp against distances computed
// independently — closed-form nearest points, or dense sampling of the
// surface (of its meridian curve, for the solids of revolution) — at random
// points; |∇f| = 1 wherever the distance is exact; the ellipsoid's bound
// never exceeds the distance; and Lipschitz bounds stay finite and small at
// the surface, which sphere tracing relies on.
#include "zeroset/expr/shapes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"

namespace zeroset {
namespace {

const ExprPoint P = coordinates();

struct Sampler {
    std::mt19937_64 rng{17};
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    Vec3d point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
};

/// The distance from q to the segment a–b in the plane, by sampling it densely.
double sampled_distance_2d(double qx, double qy, double ax, double ay, double bx, double by) {
    constexpr int n = 20000;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i) {
        const double s = static_cast<double>(i) / n;
        best = std::min(best, std::hypot(qx - (ax + s * (bx - ax)), qy - (ay + s * (by - ay))));
    }
    return best;
}

/// The signed distance to the box |p_i| ≤ b_i from its nearest point (clamping) or nearest face.
double box_distance(const Vec3d& p, const Vec3d& b) {
    const Vec3d nearest{std::clamp(p.x, -b.x, b.x), std::clamp(p.y, -b.y, b.y), std::clamp(p.z, -b.z, b.z)};
    const double outside = length(p - nearest);
    if (outside > 0.0) return outside;
    return -std::min({b.x - std::abs(p.x), b.y - std::abs(p.y), b.z - std::abs(p.z)});
}

struct Shape {
    std::string name;
    Expr f;
    std::function<double(const Vec3d&)> distance;  // the exact signed distance, computed independently
    double tolerance;                              // of that computation
};

std::vector<Shape> shapes() {
    const double h = 0.8, r1 = 0.9, r2 = 0.3;  // the capped cone
    const Vec3d a{-0.5, 0.2, -0.4}, b{0.6, -0.3, 0.5};  // the capsule
    return {
        {"sphere", sd_sphere(P, 1.1), [](const Vec3d& p) { return length(p) - 1.1; }, 1e-14},
        {"box", sd_box(P, {0.9, 0.5, 0.7}), [](const Vec3d& p) { return box_distance(p, {0.9, 0.5, 0.7}); }, 1e-14},
        {"round box", sd_round_box(P, {0.9, 0.5, 0.7}, 0.2),
         [](const Vec3d& p) { return box_distance(p, {0.7, 0.3, 0.5}) - 0.2; }, 1e-14},
        {"cylinder", sd_cylinder(P, 0.6, 0.9),
         [](const Vec3d& p) {
             const double rho = std::hypot(p.x, p.y);  // the rectangle [0, 0.6] × [−0.9, 0.9] of the meridian
             const double dr = rho - 0.6, dz = std::abs(p.z) - 0.9;
             if (dr > 0 || dz > 0) return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
             return std::max(dr, dz);
         },
         1e-14},
        {"capped cone", sd_capped_cone(P, h, r1, r2),
         [=](const Vec3d& p) {
             const double rho = std::hypot(p.x, p.y), z = p.z;
             const double d =
                 std::min({sampled_distance_2d(rho, z, 0, -h, r1, -h), sampled_distance_2d(rho, z, 0, h, r2, h),
                           sampled_distance_2d(rho, z, r1, -h, r2, h)});
             const bool inside = std::abs(z) < h && rho < r1 + (r2 - r1) * (z + h) / (2 * h);
             return inside ? -d : d;
         },
         1e-7},
        {"capsule", sd_capsule(P, a, b, 0.5),
         [=](const Vec3d& p) {
             constexpr int n = 20000;
             double best = std::numeric_limits<double>::infinity();
             for (int i = 0; i <= n; ++i)
                 best = std::min(best, length(p - (a + (b - a) * (static_cast<double>(i) / n))));
             return best - 0.5;
         },
         1e-7},
        {"torus", sd_torus(P, 1.0, 0.3),
         [](const Vec3d& p) {
             const double rho = std::hypot(p.x, p.y);  // the circle's nearest point is R·(x, y)/ρ
             const Vec3d c = rho > 0 ? Vec3d{p.x / rho, p.y / rho, 0} : Vec3d{1, 0, 0};
             return length(p - c) - 0.3;
         },
         1e-14},
        {"plane", sd_plane(P, {1, -2, 2}, 0.5), [](const Vec3d& p) { return (p.x - 2 * p.y + 2 * p.z) / 3 - 0.5; },
         1e-14},
    };
}

TEST(Shapes, AreExactSignedDistances) {
    Sampler s;
    for (const Shape& shape : shapes()) {
        SCOPED_TRACE(shape.name);
        const Tape tape(shape.f);
        Evaluator<double> eval(tape);
        Evaluator<Dual<double>> grad(tape);
        int inside = 0;
        for (int n = 0; n < 300; ++n) {
            const Vec3d p = s.point(1.6);
            const double want = shape.distance(p);
            const double got = eval(p.x, p.y, p.z);
            ASSERT_NEAR(got, want, shape.tolerance + 1e-14 * std::abs(want))
                << "at (" << p.x << ", " << p.y << ", " << p.z << ")";
            inside += got < 0;
            EXPECT_NEAR(length(evaluate_gradient(grad, p).g), 1.0, 1e-9)
                << "|∇f| at (" << p.x << ", " << p.y << ", " << p.z << ")";
        }
        EXPECT_GT(inside, 10);
        EXPECT_LT(inside, 290);
    }
}

TEST(Shapes, TheEllipsoidIsABoundNegativeInside) {
    const Vec3d radii{1.2, 0.5, 0.8};
    const Tape tape(sd_ellipsoid(P, radii));
    Evaluator<double> eval(tape);
    Evaluator<Dual<double>> grad(tape);
    // The surface sampled on a grid of angles: the sampled distance is at least the true one.
    std::vector<Vec3d> surface;
    for (int i = 0; i <= 200; ++i)
        for (int j = 0; j < 400; ++j) {
            const double theta = std::numbers::pi * i / 200, phi = 2 * std::numbers::pi * j / 400;
            surface.push_back({radii.x * std::sin(theta) * std::cos(phi), radii.y * std::sin(theta) * std::sin(phi),
                               radii.z * std::cos(theta)});
        }
    Sampler s;
    for (int n = 0; n < 200; ++n) {
        const Vec3d p = s.point(1.5);
        double sampled = std::numeric_limits<double>::infinity();
        for (const Vec3d& q : surface) sampled = std::min(sampled, length(p - q));
        const double f = eval(p.x, p.y, p.z);
        const double k = std::hypot(std::hypot(p.x / radii.x, p.y / radii.y), p.z / radii.z);
        EXPECT_EQ(f < 0, k < 1) << "the sign is the side";
        EXPECT_LE(std::abs(f), sampled + 1e-12) << "a bound: never more than the distance";
        EXPECT_LE(length(evaluate_gradient(grad, p).g), 1.0 + 1e-12);
    }
    EXPECT_LT(eval(0, 0, 0), 0.0);  // defined (and inside) at the centre
    EXPECT_NEAR(eval(1.2, 0, 0), 0.0, 1e-15);
}

TEST(Shapes, LipschitzBoundsStayFiniteAtTheSurface) {
    Sampler s;
    for (const Shape& shape : shapes()) {
        SCOPED_TRACE(shape.name);
        const Tape tape(shape.f);
        Evaluator<double> eval(tape);
        Evaluator<Dual<Interval>> slope(tape);
        for (int n = 0; n < 200; ++n) {
            const Vec3d c = s.point(1.5);
            const double w = std::pow(10.0, s.uniform(-6, -0.5));
            const Box3 box{c - Vec3d{w, w, w}, c + Vec3d{w, w, w}};
            const LipschitzBound bound = lipschitz_bound(slope, box);
            ASSERT_TRUE(bound.value.contains(eval(c.x, c.y, c.z)));
            ASSERT_LE(bound.constant, 8.0) << "over a box of half-size " << w << " at (" << c.x << ", " << c.y
                                           << ", " << c.z << ")";
        }
    }
}

TEST(Shapes, ParametersThatMakeNoShapeAreRefused) {
    EXPECT_THROW(sd_sphere(P, 0.0), std::invalid_argument);
    EXPECT_THROW(sd_box(P, {1, -1, 1}), std::invalid_argument);
    EXPECT_THROW(sd_round_box(P, {1, 0.5, 1}, 0.6), std::invalid_argument);
    EXPECT_THROW(sd_cylinder(P, 1, 0), std::invalid_argument);
    EXPECT_THROW(sd_capped_cone(P, 1, 0, 0), std::invalid_argument);
    EXPECT_THROW(sd_capped_cone(P, 1, -0.5, 1), std::invalid_argument);
    EXPECT_THROW(sd_capsule(P, {0, 0, 0}, {1, 0, 0}, -1), std::invalid_argument);
    EXPECT_THROW(sd_torus(P, 1, 0), std::invalid_argument);
    EXPECT_THROW(sd_plane(P, {0, 0, 0}, 1), std::invalid_argument);
    EXPECT_THROW(sd_ellipsoid(P, {1, 1, 0}), std::invalid_argument);
    try {
        sd_torus(P, -2, 0.5);
        ADD_FAILURE();
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "the major radius R must be positive, but it is -2");
    }
}

}  // namespace
}  // namespace zeroset
