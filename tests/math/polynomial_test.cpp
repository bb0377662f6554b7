// Polynomial in t: exact arithmetic on coefficients, a fixed capacity that
// refuses to overflow, and a NotPolynomial state for everything else.
#include <gtest/gtest.h>

#include <array>

#include "zeroset/math/polynomial.hpp"

namespace zeroset {
namespace {

using State = Polynomial::State;

Polynomial poly(std::initializer_list<double> c) {
    return Polynomial::from_coefficients(std::span<const double>(c.begin(), c.size()));
}

TEST(Polynomial, ArithmeticOnCoefficients) {
    const Polynomial p = poly({1.0, 2.0});   // 1 + 2t
    const Polynomial q = poly({-1.0, 0.0, 3.0});  // −1 + 3t²
    EXPECT_EQ((p + q).to_string(), "2 t + 3 t^2");
    EXPECT_EQ((p - q).to_string(), "2 + 2 t - 3 t^2");
    EXPECT_EQ((p * q).to_string(), "-1 - 2 t + 3 t^2 + 6 t^3");
    EXPECT_EQ((-p).to_string(), "-1 - 2 t");
    EXPECT_EQ(square(p).to_string(), "1 + 4 t + 4 t^2");
    EXPECT_EQ((p / Polynomial(2.0)).to_string(), "0.5 + 1 t");
    EXPECT_EQ(Polynomial::line(3.0, -0.5).to_string(), "3 - 0.5 t");
}

TEST(Polynomial, PowiMatchesRepeatedProducts) {
    const Polynomial p = poly({1.0, 1.0});
    Polynomial expected(1.0);
    for (int n = 0; n <= 12; ++n) {
        EXPECT_EQ(powi(p, n).to_string(), expected.to_string()) << n;
        expected = expected * p;
    }
    EXPECT_EQ(powi(p, 5)[2], 10.0);
    EXPECT_EQ(pow(p, Polynomial(3.0)).to_string(), powi(p, 3).to_string());
}

TEST(Polynomial, HornerAndDerivative) {
    const Polynomial p = poly({-2.0, 0.0, 1.0, 4.0});
    EXPECT_EQ(p(2.0), -2.0 + 4.0 + 32.0);
    EXPECT_EQ(p.derivative().to_string(), "2 t + 12 t^2");
    EXPECT_EQ(Polynomial(5.0).derivative().to_string(), "0");
}

TEST(Polynomial, CancellationTrimsTheDegree) {
    const Polynomial t = Polynomial::line(0.0, 1.0);
    const Polynomial p = square(t + Polynomial(1.0)) - square(t);
    EXPECT_EQ(p.degree(), 1);
    EXPECT_EQ(p.to_string(), "1 + 2 t");
}

TEST(Polynomial, Degree32IsTheCapacity) {
    const Polynomial p = poly({1.0, 1.0});
    const Polynomial d16 = powi(p, 16);
    ASSERT_TRUE(d16.valid());
    const Polynomial d32 = d16 * d16;
    ASSERT_TRUE(d32.valid());
    EXPECT_EQ(d32.degree(), 32);
    EXPECT_EQ(d32[16], 601080390.0);  // C(32, 16)
    EXPECT_EQ((d32 * p).state(), State::Overflow);
    EXPECT_EQ(powi(p, 33).state(), State::Overflow);
    EXPECT_EQ(square(powi(p, 17)).state(), State::Overflow);
    // Sticky: cancelling later does not bring it back.
    const Polynomial o = d32 * p;
    EXPECT_EQ((o - o).state(), State::Overflow);
    EXPECT_EQ(o.to_string(), "overflow");
    const std::array<double, 34> too_many{};
    EXPECT_EQ(Polynomial::from_coefficients(too_many).state(), State::Overflow);
}

TEST(Polynomial, NonPolynomialOpsAreRefused) {
    const Polynomial t = Polynomial::line(1.0, 1.0);
    const Polynomial two(2.0);
    for (const Polynomial& p : {sqrt(t), abs(t), exp(t), log(t), sin(t), cos(t), t / t, two / t,
                                t / Polynomial(0.0), powi(t, -1), pow(t, Polynomial(0.5)), pow(two, t),
                                min(t, two), max(two, t), tan(t), atan(t), floor(t), atan2(t, two), atan2(two, t),
                                hypot(t, two)}) {
        EXPECT_EQ(p.state(), State::NotPolynomial) << p.to_string();
    }
    EXPECT_EQ((sqrt(t) + t).to_string(), "not a polynomial");
    EXPECT_EQ((sqrt(t) * powi(t, 40)).state(), State::NotPolynomial);
}

TEST(Polynomial, FunctionsOfConstantsAreConstants) {
    EXPECT_EQ(sqrt(Polynomial(4.0)).to_string(), "2");
    EXPECT_EQ(min(Polynomial(4.0), Polynomial(-1.0)).to_string(), "-1");
    EXPECT_EQ(powi(Polynomial(2.0), -2).to_string(), "0.25");
    EXPECT_EQ(pow(Polynomial(4.0), Polynomial(0.5)).to_string(), "2");
    EXPECT_TRUE(exp(Polynomial(0.0)).is_constant());
    EXPECT_EQ(floor(Polynomial(-2.5)).to_string(), "-3");
    EXPECT_EQ(hypot(Polynomial(3.0), Polynomial(4.0)).to_string(), "5");
    EXPECT_EQ(atan2(Polynomial(0.0), Polynomial(1.0)).to_string(), "0");
    EXPECT_EQ(tan(Polynomial(0.0)).to_string(), "0");
    EXPECT_EQ(atan(Polynomial(0.0)).to_string(), "0");
}

}  // namespace
}  // namespace zeroset
