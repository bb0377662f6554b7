// F(t) = f∘r(t) as exact coefficients (survey eqs. 8–11), and the structural
// degree that says in advance whether that is possible.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/ray_polynomial.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

TEST(RayPolynomial, SurveySphereGivesEquation10) {
    const Tape tape(square(X - 1.2) + square(Y) + square(Z) - 1.0);
    const Ray ray{{-4.905, -0.67, 0.364}, {0.981, 0.174, 0.0872}};
    const auto f = ray_polynomial(tape, ray);
    ASSERT_TRUE(f);
    ASSERT_EQ(f->degree(), 2);
    EXPECT_NEAR((*f)[2], 1.00024084, 1e-14);
    EXPECT_NEAR((*f)[1], -12.1476884, 1e-13);
    EXPECT_NEAR((*f)[0], 36.852421, 1e-13);
    EXPECT_EQ(polynomial_degree(tape), 2);
}

TEST(RayPolynomial, TorusGivesAQuartic) {
    const double R = 1.0, r = 0.25;
    const Expr s = square(X) + square(Y) + square(Z) + (R * R - r * r);
    const Tape tape(square(s) - 4.0 * R * R * (square(X) + square(Y)));
    const Ray ray{{-3.0, 0.1, 0.05}, {1.0, 0.0, 0.0}};
    const auto f = ray_polynomial(tape, ray);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->degree(), 4);
    EXPECT_EQ(polynomial_degree(tape), 4);
    Evaluator<double> eval(tape);
    for (double t : {0.0, 1.3, 2.0, 2.9, 4.5}) {
        const Vec3d p = ray.at(t);
        EXPECT_NEAR((*f)(t), eval(p.x, p.y, p.z), 1e-12 * (1.0 + std::fabs(eval(p.x, p.y, p.z)))) << t;
    }
}

TEST(RayPolynomial, NonPolynomialTapesGiveNothing) {
    const Ray ray{{0.1, 0.2, -3.0}, {0.3, 0.2, 0.9}};  // every coordinate varies
    for (const Expr& f : {sqrt(square(X) + square(Y) + square(Z)) - 1.0, exp(-X) - 0.5, min(X, Y), X / (Y + 2.0),
                          pow(X, Y), powi(X, -2)}) {
        const Tape tape(f);
        EXPECT_FALSE(ray_polynomial(tape, ray));
        EXPECT_EQ(polynomial_degree(tape), -1);
    }
}

TEST(RayPolynomial, DivisionByConstantsAndConstantFunctionsArePolynomial) {
    const Tape tape(square(X) / 4.0 + pow(Y, Expr(3.0)) - sqrt(Expr(2.0)) * Z);
    EXPECT_EQ(polynomial_degree(tape), 3);
    const auto f = ray_polynomial(tape, {{0.0, 0.0, 0.0}, {2.0, 1.0, 1.0}});
    ASSERT_TRUE(f);
    EXPECT_EQ(f->to_string(), Polynomial::from_coefficients(
                                  std::array{0.0, -std::sqrt(2.0), 1.0, 1.0}).to_string());
}

TEST(RayPolynomial, Degree16WorksAndOverflowIsRefused) {
    const Expr q = square(X) + square(Y) + square(Z) - 1.0;
    const Ray ray{{0.1, -0.2, 0.3}, {0.6, 0.0, 0.8}};
    const Tape d16(powi(q, 8));
    EXPECT_EQ(polynomial_degree(d16), 16);
    const auto f = ray_polynomial(d16, ray);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->degree(), 16);
    const Vec3d p = ray.at(0.7);
    const double expected = std::pow(p.x * p.x + p.y * p.y + p.z * p.z - 1.0, 8);
    EXPECT_NEAR((*f)(0.7), expected, 1e-13);

    const Tape d34(powi(q, 17));
    EXPECT_FALSE(ray_polynomial(d34, ray));
    EXPECT_EQ(polynomial_degree(d34), Polynomial::max_degree + 1);
    EXPECT_EQ(polynomial_degree(Tape(powi(powi(q, 1 << 20), 1 << 20))), Polynomial::max_degree + 1);
}

}  // namespace
}  // namespace zeroset
