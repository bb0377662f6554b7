// The composite functions of expr/functions.hpp: their values against the
// formulas written out in doubles, the smooth blends' documented properties
// (exactly min/max away from the blend, below/above it within k/4, a
// 1-Lipschitz blend of distance functions), and — being ordinary expressions
// — sound interval and gradient enclosures.
#include "zeroset/expr/functions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

double at(const Expr& f, double x, double y = 0.0, double z = 0.0) {
    const Tape tape(f);
    Evaluator<double> eval(tape);
    return eval(x, y, z);
}

TEST(Functions, ValuesMatchTheirFormulas) {
    for (const double a : {-3.7, -1.0, -0.2, 0.0, 0.4, 2.5, 7.0}) {
        for (const double b : {-2.0, 0.75, 3.0}) {
            EXPECT_NEAR(at(mod(X, Y), a, b), a - b * std::floor(a / b), 1e-15) << a << " mod " << b;
            // GLSL's mod has the sign of b: 0 ≤ mod < b for b > 0, b < mod ≤ 0 for b < 0.
            const double m = at(mod(X, Y), a, b);
            EXPECT_TRUE(b > 0 ? (m >= 0 && m < b) : (m <= 0 && m > b)) << a << " mod " << b << " = " << m;
        }
        EXPECT_EQ(at(clamp(X, Expr(-1.0), Expr(2.0)), a), std::clamp(a, -1.0, 2.0));
        EXPECT_DOUBLE_EQ(at(mix(Y, Z, X), a, 2.0, -3.0), 2.0 + (-3.0 - 2.0) * a);
        const double s = std::clamp((a - (-1.0)) / (2.5 - (-1.0)), 0.0, 1.0);
        EXPECT_DOUBLE_EQ(at(smoothstep(Expr(-1.0), Expr(2.5), X), a), s * s * (3 - 2 * s));
    }
    EXPECT_EQ(at(smoothstep(Expr(0.0), Expr(1.0), X), -5.0), 0.0);
    EXPECT_EQ(at(smoothstep(Expr(0.0), Expr(1.0), X), 0.5), 0.5);
    EXPECT_EQ(at(smoothstep(Expr(0.0), Expr(1.0), X), 9.0), 1.0);
    EXPECT_THROW(smooth_union(X, Y, 0.0), std::invalid_argument);
    EXPECT_THROW(smooth_union(X, Y, -1.0), std::invalid_argument);
}

struct Sampler {
    std::mt19937_64 rng{7};
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    Vec3d point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
};

// Two unit balls 1.2 apart: exact distance functions, so 1-Lipschitz.
const Expr ball_a = sqrt(square(X - 0.6) + square(Y) + square(Z)) - 1.0;
const Expr ball_b = sqrt(square(X + 0.6) + square(Y - 0.3) + square(Z)) - 1.0;
constexpr double k = 0.5;

TEST(Functions, SmoothBlendsKeepTheirPromises) {
    const Tape a_tape(ball_a), b_tape(ball_b);
    const Tape u_tape(smooth_union(ball_a, ball_b, k)), i_tape(smooth_intersection(ball_a, ball_b, k));
    const Tape d_tape(smooth_difference(ball_a, ball_b, k)), di_tape(smooth_intersection(ball_a, -ball_b, k));
    Evaluator<double> a(a_tape), b(b_tape), u(u_tape), i(i_tape), d(d_tape), di(di_tape);
    Evaluator<Dual<double>> ug(u_tape), ig(i_tape);
    Sampler s;
    int blended = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3d p = s.point(2.5);
        const double va = a(p.x, p.y, p.z), vb = b(p.x, p.y, p.z);
        const double vu = u(p.x, p.y, p.z), vi = i(p.x, p.y, p.z);
        if (std::abs(va - vb) >= k) {
            EXPECT_EQ(vu, std::min(va, vb));
            EXPECT_EQ(vi, std::max(va, vb));
        } else {
            ++blended;
            EXPECT_LE(vu, std::min(va, vb) + 1e-15);
            EXPECT_GE(vu, std::min(va, vb) - k / 4 - 1e-15);
            EXPECT_GE(vi, std::max(va, vb) - 1e-15);
            EXPECT_LE(vi, std::max(va, vb) + k / 4 + 1e-15);
        }
        EXPECT_EQ(d(p.x, p.y, p.z), di(p.x, p.y, p.z));
        // A blend of 1-Lipschitz functions is 1-Lipschitz.
        EXPECT_LE(length(evaluate_gradient(ug, p).g), 1.0 + 1e-12);
        EXPECT_LE(length(evaluate_gradient(ig, p).g), 1.0 + 1e-12);
    }
    EXPECT_GT(blended, 100);
    // At a = b the union is min − k/4, exactly.
    EXPECT_NEAR(u(0.0, 0.15, 0.0) - a(0.0, 0.15, 0.0), -k / 4, 1e-12);
}

TEST(Functions, EnclosuresAreSound) {
    const std::vector<Expr> functions = {smooth_union(ball_a, ball_b, k), smooth_difference(ball_a, ball_b, k),
                                         mod(X + 0.3 * Y, Expr(0.7)), smoothstep(Expr(-0.5), Expr(0.5), X * Y + Z),
                                         mix(ball_a, ball_b, clamp(X, Expr(0.0), Expr(1.0)))};
    Sampler s;
    for (const Expr& f : functions) {
        SCOPED_TRACE(f.to_string());
        const Tape tape(f);
        Evaluator<double> eval(tape);
        Evaluator<Interval> box_eval(tape);
        Evaluator<Dual<Interval>> slope_eval(tape);
        for (int n = 0; n < 200; ++n) {
            const Vec3d c = s.point(2.0);
            const double w = std::pow(10.0, s.uniform(-4, 0));
            const Interval bx(c.x - w, c.x + w), by(c.y - w, c.y + w), bz(c.z - w, c.z + w);
            const Interval enclosure = box_eval(bx, by, bz);
            const Dual<Interval> slope = slope_eval(Dual<Interval>::variable(bx, 0), Dual<Interval>::variable(by, 1),
                                                    Dual<Interval>::variable(bz, 2));
            for (int m = 0; m < 10; ++m) {
                const Vec3d p{s.uniform(bx.lo, bx.hi), s.uniform(by.lo, by.hi), s.uniform(bz.lo, bz.hi)};
                const double v = eval(p.x, p.y, p.z);
                ASSERT_TRUE(enclosure.contains(v)) << v << " at " << p.x << ", " << p.y << ", " << p.z;
                // Central differences lie in the gradient enclosure (mean value theorem),
                // when the step stays in the box.
                const double h = 1e-3 * w;
                for (int axis = 0; axis < 3; ++axis) {
                    Vec3d q = p, r = p;
                    q[axis] = std::min(p[axis] + h, c[axis] + w);
                    r[axis] = std::max(p[axis] - h, c[axis] - w);
                    const double fd = (eval(q.x, q.y, q.z) - eval(r.x, r.y, r.z)) / (q[axis] - r[axis]);
                    const double slack = 1e-9 * (1 + std::abs(fd));
                    ASSERT_GE(fd, slope.g[axis].lo - slack) << "axis " << axis;
                    ASSERT_LE(fd, slope.g[axis].hi + slack) << "axis " << axis;
                }
            }
        }
    }
}

}  // namespace
}  // namespace zeroset
