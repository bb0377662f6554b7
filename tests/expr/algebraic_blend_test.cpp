// Hoffman and Hopcroft's algebraic blend (survey §3.3): checked against what
// the potential method promises, computed independently of the formula in
// expr/functions.cpp — the tangency of the blend to each primary surface
// along the offset curve of the other, the fillet's profile worked out by
// hand from the parabola √(s/a) + √(t/b) = 1, which side is inside, and that
// the blend of polynomials stays a polynomial (degree 2·max).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/ray_polynomial.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

// The foot of scenes/blends/pipe_junction.zs: a post of radius r on a plate.
constexpr double r = 0.5, a = 0.36, b = 0.3;
const Expr post = square(X) + square(Z) - r * r;
const Expr plate = Y;

/// |u × v| / (|u| |v|): the sine of the angle between two directions.
double sine_between(const Vec3d& u, const Vec3d& v) { return length(cross(u, v)) / (length(u) * length(v)); }

TEST(AlgebraicBlend, TouchesEachSurfaceAlongTheOffsetOfTheOther) {
    const Tape blend(algebraic_blend(post, plate, a, b));
    Evaluator<double> value(blend);
    Evaluator<Dual<double>> gradient(blend);
    for (int k = 0; k < 24; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / 24.0 + 0.1;
        // On the plate (h = 0) where the post's potential is a: radius √(r² + a).
        const double wide = std::sqrt(r * r + a);
        const Vec3d on_plate{wide * std::cos(phi), 0.0, wide * std::sin(phi)};
        EXPECT_NEAR(value(on_plate.x, on_plate.y, on_plate.z), 0.0, 1e-15);
        // Tangent to the plate: the blend's gradient is the plate's, (0, 1, 0).
        EXPECT_LT(sine_between(evaluate_gradient(gradient, on_plate).g, {0.0, 1.0, 0.0}), 1e-14);
        // On the post (g = 0) at the height h = b, tangent to the post.
        const Vec3d on_post{r * std::cos(phi), b, r * std::sin(phi)};
        EXPECT_NEAR(value(on_post.x, on_post.y, on_post.z), 0.0, 1e-15);
        const Vec3d post_normal{on_post.x, 0.0, on_post.z};
        EXPECT_LT(sine_between(evaluate_gradient(gradient, on_post).g, post_normal), 1e-14);
    }
}

TEST(AlgebraicBlend, FollowsTheParabolaBetweenTheTangentCurves) {
    // √(g/a) + √(h/b) = 1 gives the fillet's height over the plate at the
    // radius ρ: h = b·(1 − √((ρ² − r²)/a))².
    const Tape blend(algebraic_blend(post, plate, a, b));
    Evaluator<double> value(blend);
    for (int k = 0; k <= 50; ++k) {
        const double rho = r + (std::sqrt(r * r + a) - r) * k / 50.0;
        const double height = b * square(1.0 - std::sqrt((rho * rho - r * r) / a));
        EXPECT_NEAR(value(rho * 0.6, height, rho * 0.8), 0.0, 1e-14) << "rho " << rho;
        // Strictly between the ends: the fillet's material is on the side of
        // the corner, beyond the arc is air.
        if (k == 0 || k == 50) continue;
        EXPECT_LT(value(rho * 0.6, 0.9 * height, rho * 0.8), 0.0) << "rho " << rho;
        EXPECT_GT(value(rho * 0.6, 1.1 * height + 1e-3, rho * 0.8), 0.0) << "rho " << rho;
    }
    // Inside one solid and outside the other the blend is negative too (it
    // is hidden there when the solids' objects cover the clipped region).
    EXPECT_LT(value(0.2, 0.2, 0.0), 0.0);   // in the post, above the plate
    EXPECT_LT(value(0.7, -0.1, 0.0), 0.0);  // in the plate, beside the post
    // Beyond g = a the parabola's other branch makes it negative again: why
    // the fillet is clipped to g ≤ a and h ≤ b.
    EXPECT_LT(value(1.0, 0.05, 0.0), 0.0);
}

TEST(AlgebraicBlend, OfPolynomialsIsAPolynomial) {
    const Expr pipe = square(Y - 1.2) + square(Z) - 0.09;
    EXPECT_EQ(polynomial_degree(Tape(algebraic_blend(post, plate, a, b))), 4);
    EXPECT_EQ(polynomial_degree(Tape(algebraic_blend(post, pipe, 0.2, 0.12))), 4);
    const Expr torus = square(square(X) + square(Y) + square(Z) + 0.75) - 4.0 * (square(X) + square(Y));
    EXPECT_EQ(polynomial_degree(Tape(algebraic_blend(torus, plate, 0.2, 0.12))), 8);
    EXPECT_THROW(algebraic_blend(post, plate, 0.0, b), std::invalid_argument);
    EXPECT_THROW(algebraic_blend(post, plate, a, -1.0), std::invalid_argument);
    EXPECT_THROW(algebraic_blend(post, plate, a, INFINITY), std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
