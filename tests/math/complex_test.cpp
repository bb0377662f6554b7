// Complex against std::complex (the oracle for every analytic op), against the
// real functions on the real axis, and against the identities its principal
// branches must keep; plus the documented branch rules of abs, min, max,
// floor and atan2.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "zeroset/math/complex.hpp"

namespace zeroset {
namespace {

using Std = std::complex<double>;

Std to_std(Complex a) { return {a.re, a.im}; }

/// |a − b| ≤ tolerance · max(1, |b|).
::testing::AssertionResult near(Complex a, Std b, double tolerance = 1e-13) {
    const double error = std::abs(to_std(a) - b);
    if (error <= tolerance * std::max(1.0, std::abs(b))) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.re << ", " << a.im << ") vs " << b << ", error " << error;
}
::testing::AssertionResult near(Complex a, Complex b, double tolerance = 1e-13) {
    return near(a, to_std(b), tolerance);
}

// Points in every quadrant, near the axes and far from the origin; none on
// the negative real axis, where the principal branches are cut.
const std::vector<Complex> samples = {{0.3, 0.4}, {-1.2, 0.7},  {2.5, -1.1}, {-0.4, -2.2},
                                      {1e-3, 5.0}, {-3.0, 0.25}, {7.5, 0.0},  {0.0, -1.5}};
const std::vector<double> reals = {-2.5, -0.3, 0.0, 0.7, 3.2};

TEST(Complex, ArithmeticAgreesWithStdComplex) {
    for (const Complex a : samples) {
        EXPECT_TRUE(near(-a, -to_std(a)));
        for (const Complex b : samples) {
            EXPECT_TRUE(near(a + b, to_std(a) + to_std(b)));
            EXPECT_TRUE(near(a - b, to_std(a) - to_std(b)));
            EXPECT_TRUE(near(a * b, to_std(a) * to_std(b)));
            EXPECT_TRUE(near(a / b, to_std(a) / to_std(b)));
            EXPECT_TRUE(near((a / b) * b, a, 1e-14));
        }
    }
}

TEST(Complex, ElementaryFunctionsAgreeWithStdComplex) {
    for (const Complex a : samples) {
        const Std s = to_std(a);
        EXPECT_TRUE(near(square(a), s * s));
        EXPECT_TRUE(near(sqrt(a), std::sqrt(s)));
        EXPECT_TRUE(near(exp(a), std::exp(s)));
        EXPECT_TRUE(near(sin(a), std::sin(s)));
        EXPECT_TRUE(near(cos(a), std::cos(s)));
        EXPECT_TRUE(near(tan(a), std::tan(s)));
        EXPECT_TRUE(near(atan(a), std::atan(s)));
        if (a.re != 0.0 || a.im != 0.0) { EXPECT_TRUE(near(log(a), std::log(s))); }
        for (const int n : {0, 1, 2, 3, 7, -1, -4}) EXPECT_TRUE(near(powi(a, n), std::pow(s, n), 1e-12)) << n;
        for (const Complex b : samples) EXPECT_TRUE(near(pow(a, b), std::pow(s, to_std(b)), 1e-12));
    }
}

TEST(Complex, Identities) {
    for (const Complex a : samples) {
        EXPECT_TRUE(near(exp(log(a)), a));
        EXPECT_TRUE(near(square(sqrt(a)), a));
        EXPECT_GE(sqrt(a).re, 0.0);  // the principal root
        // The sum cancels terms as large as |sin a|², and so loses their digits.
        const double size = modulus(sin(a)) * modulus(sin(a)) + modulus(cos(a)) * modulus(cos(a));
        EXPECT_TRUE(near(square(sin(a)) + square(cos(a)), Complex(1.0), 1e-15 * size));
        EXPECT_TRUE(near(pow(a, Complex(0.5)), sqrt(a)));
        EXPECT_TRUE(near(powi(a, -3) * powi(a, 3), Complex(1.0)));
        EXPECT_TRUE(near(powi(a, 5), a * a * a * a * a));
        for (const Complex b : samples) {
            EXPECT_TRUE(near(exp(a + b), exp(a) * exp(b), 1e-12));
            EXPECT_TRUE(near(pow(a, b), exp(b * log(a)), 1e-12));
        }
    }
}

TEST(Complex, PrincipalBranches) {
    EXPECT_TRUE(near(sqrt(Complex(-4.0)), Std(0.0, 2.0)));
    EXPECT_TRUE(near(log(Complex(-1.0)), Std(0.0, std::numbers::pi)));
    EXPECT_TRUE(near(pow(Complex(-8.0), Complex(1.0 / 3.0)), Std(1.0, std::sqrt(3.0))));
    // An integral exponent takes no branch: exact, as for plain numbers.
    EXPECT_EQ(pow(Complex(-2.0), Complex(3.0)), Complex(-8.0));
    EXPECT_EQ(pow(Complex(0.0), Complex(2.5)), Complex(0.0));
}

TEST(Complex, RealAxisAgreesWithDouble) {
    for (const double x : reals) {
        const Complex z(x);
        EXPECT_TRUE(near(square(z), Complex(x * x)));
        EXPECT_TRUE(near(-z, Complex(-x)));
        EXPECT_TRUE(near(abs(z), Complex(std::abs(x))));
        EXPECT_TRUE(near(exp(z), Complex(std::exp(x))));
        EXPECT_TRUE(near(sin(z), Complex(std::sin(x))));
        EXPECT_TRUE(near(cos(z), Complex(std::cos(x))));
        EXPECT_TRUE(near(tan(z), Complex(std::tan(x))));
        EXPECT_TRUE(near(atan(z), Complex(std::atan(x))));
        EXPECT_EQ(floor(z), Complex(std::floor(x)));
        for (const int n : {0, 1, 2, 3, -2}) {
            if (x != 0.0 || n >= 0) { EXPECT_TRUE(near(powi(z, n), Complex(powi(x, n)))) << x << "^" << n; }
        }
        if (x > 0.0) {
            EXPECT_TRUE(near(sqrt(z), Complex(std::sqrt(x))));
            EXPECT_TRUE(near(log(z), Complex(std::log(x))));
        }
        for (const double y : reals) {
            const Complex w(y);
            EXPECT_TRUE(near(z + w, Complex(x + y)));
            EXPECT_TRUE(near(z - w, Complex(x - y)));
            EXPECT_TRUE(near(z * w, Complex(x * y)));
            if (y != 0.0) { EXPECT_TRUE(near(z / w, Complex(x / y))); }
            EXPECT_EQ(min(z, w).re, std::min(x, y));
            EXPECT_EQ(max(z, w).re, std::max(x, y));
            EXPECT_TRUE(near(hypot(z, w), Complex(std::hypot(x, y))));
            // atan2 continued as the angle of x + iy is the real atan2.
            if (x != 0.0 || y != 0.0) { EXPECT_TRUE(near(atan2(w, z), Complex(std::atan2(y, x)))) << y << ", " << x; }
            const double p = std::pow(x, y);
            if (std::isfinite(p)) { EXPECT_TRUE(near(pow(z, w), Complex(p))) << x << "^" << y; }
        }
    }
}

TEST(Complex, AbsMinMaxPickTheBranchByRealPart) {
    for (const Complex a : samples) {
        // √(z²) on the principal branch, and z itself on the imaginary axis.
        if (a.re != 0.0) { EXPECT_TRUE(near(abs(a), sqrt(square(a)))); }
        EXPECT_EQ(abs(a), a.re >= 0.0 ? a : -a);
        for (const Complex b : samples) {
            EXPECT_EQ(min(a, b), a.re <= b.re ? a : b);
            EXPECT_EQ(max(a, b), a.re >= b.re ? a : b);
        }
    }
    const Complex nan(std::numeric_limits<double>::quiet_NaN(), 0.0);
    EXPECT_TRUE(std::isnan(min(nan, Complex(1.0)).re));
    EXPECT_TRUE(std::isnan(max(Complex(1.0), nan).re));
}

TEST(Complex, Atan2IsTheAngleOfXPlusIY) {
    // The continuation keeps the real identities tan(atan2(y, x)) = y/x and
    // cos(atan2(y, x)) = x/√(x² + y²) off the real axis too.
    for (const Complex x : samples) {
        for (const Complex y : samples) {
            const Complex r = hypot(x, y);
            if (modulus(r) < 1e-3) continue;  // near the branch point x² + y² = 0
            EXPECT_TRUE(near(tan(atan2(y, x)), y / x, 1e-11));
            EXPECT_TRUE(near(cos(atan2(y, x)), x / r, 1e-11));
        }
    }
    EXPECT_TRUE(near(atan2(Complex(0.0), Complex(-1.0)), Complex(std::numbers::pi)));
    EXPECT_EQ(floor(Complex(2.5, -3.0)), Complex(2.0));  // ⌊Re z⌋: constant on each strip
}

TEST(Complex, IntegerValueAndExactZero) {
    EXPECT_EQ(integer_value(Complex(3.0)), 3);
    EXPECT_EQ(integer_value(Complex(-2.0)), -2);
    EXPECT_EQ(integer_value(Complex(2.5)), std::nullopt);
    EXPECT_EQ(integer_value(Complex(3.0, 1e-300)), std::nullopt);
    EXPECT_TRUE(is_exact_zero(Complex()));
    EXPECT_FALSE(is_exact_zero(Complex(0.0, 1e-300)));
    EXPECT_EQ(modulus(Complex(3.0, -4.0)), 5.0);
    EXPECT_FALSE(is_finite(Complex(1.0, std::numeric_limits<double>::infinity())));
}

}  // namespace
}  // namespace zeroset
