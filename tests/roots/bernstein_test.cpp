// The conversion to the Bernstein basis (roots/bernstein.hpp): its
// coefficients reproduce the polynomial, within the rounding bound it
// states, on the unrolled degrees (1 to 8) and the general loop alike; and
// the split at the middle gives de Casteljau's bits, in place or not.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "zeroset/roots/bernstein.hpp"

namespace zeroset {
namespace {

/// The Bernstein form's value at u in [0, 1], by de Casteljau in long double.
long double de_casteljau(const PolynomialScratch& b, int n, long double u) {
    std::array<long double, max_polynomial_degree + 1> c{};
    for (int i = 0; i <= n; ++i) c[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i)];
    for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i)
            c[static_cast<std::size_t>(i)] = (1 - u) * c[static_cast<std::size_t>(i)] + u * c[static_cast<std::size_t>(i) + 1];
    return c[0];
}

/// The exact Bernstein coefficients of p on [t0, t1], near enough: the same
/// conversion in long double (11 more bits than the result's rounding).
std::vector<long double> reference_bernstein(const std::vector<double>& p, int n, long double t0, long double t1) {
    std::vector<long double> a(p.begin(), p.end());
    for (int i = 0; i < n; ++i)
        for (int j = n - 1; j >= i; --j) a[static_cast<std::size_t>(j)] += t0 * a[static_cast<std::size_t>(j) + 1];
    long double scale = 1;
    for (int i = 0; i <= n; ++i, scale *= t1 - t0) a[static_cast<std::size_t>(i)] *= scale;
    std::vector<long double> b(a.size(), 0);
    const auto choose = [](int m, int k) {
        long double c = 1;
        for (int i = 1; i <= k; ++i) c = c * (m - k + i) / i;
        return c;
    };
    for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= k; ++i) b[static_cast<std::size_t>(k)] += choose(k, i) / choose(n, i) * a[static_cast<std::size_t>(i)];
    return b;
}

TEST(Bernstein, TheCoefficientsAreThePolynomialsWithinTheirStatedRounding) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coefficient(-3.0, 3.0);
    std::uniform_real_distribution<double> end(-4.0, 4.0);
    for (int n = 0; n <= 12; ++n) {  // 1–8 unrolled, 0 and 9–12 by the loop
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<double> p(static_cast<std::size_t>(n) + 1);
            for (double& c : p) c = coefficient(random);
            double t0 = end(random), t1 = end(random);
            if (t0 > t1) std::swap(t0, t1);
            double magnitude = 0.0;
            PolynomialScratch b;
            to_bernstein(p, n, t0, t1, b, magnitude);
            const double noise = bernstein_noise(n, magnitude);
            const std::vector<long double> exact = reference_bernstein(p, n, t0, t1);
            for (int k = 0; k <= n; ++k) {
                const long double error = std::fabs(static_cast<long double>(b[static_cast<std::size_t>(k)]) -
                                                    exact[static_cast<std::size_t>(k)]);
                ASSERT_LE(error, noise) << "degree " << n << ", coefficient " << k;
            }
            // The Bernstein form is the polynomial: compare at a few points.
            for (const long double u : {0.0L, 0.3L, 0.5L, 0.9L, 1.0L}) {
                const long double t = t0 + u * (static_cast<long double>(t1) - t0);
                long double value = 0;
                for (int i = n; i >= 0; --i) value = value * t + p[static_cast<std::size_t>(i)];
                EXPECT_NEAR(static_cast<double>(de_casteljau(b, n, u)), static_cast<double>(value), 4.0 * noise + 1e-300)
                    << "degree " << n << " at u = " << static_cast<double>(u);
            }
        }
    }
}

/// de Casteljau at the middle, as the textbook writes it.
void reference_split(const std::vector<double>& b, int n, std::vector<double>& left, std::vector<double>& right) {
    std::vector<double> w = b;
    left.assign(b.size(), 0.0);
    right.assign(b.size(), 0.0);
    left[0] = w[0];
    right[static_cast<std::size_t>(n)] = w[static_cast<std::size_t>(n)];
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i)
            w[static_cast<std::size_t>(i)] = 0.5 * (w[static_cast<std::size_t>(i)] + w[static_cast<std::size_t>(i) + 1]);
        left[static_cast<std::size_t>(r)] = w[0];
        right[static_cast<std::size_t>(n - r)] = w[static_cast<std::size_t>(n - r)];
    }
}

TEST(Bernstein, TheSplitGivesDeCasteljausBitsOnEveryDegreeAndInPlace) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> coefficient(-5.0, 5.0);
    for (int n = 1; n <= 12; ++n) {  // 1–8 unrolled, 9–12 by the loop
        for (int trial = 0; trial < 100; ++trial) {
            std::vector<double> b(static_cast<std::size_t>(n) + 1);
            for (double& c : b) c = coefficient(random);
            std::vector<double> want_left, want_right;
            reference_split(b, n, want_left, want_right);
            std::vector<double> left(b.size()), right(b.size());
            split_bernstein(b.data(), n, left.data(), right.data());
            EXPECT_EQ(left, want_left) << "degree " << n;
            EXPECT_EQ(right, want_right) << "degree " << n;
            // Either half may take b's place (the subdivision splits so).
            std::vector<double> in_place = b;
            std::fill(left.begin(), left.end(), 0.0);
            split_bernstein(in_place.data(), n, left.data(), in_place.data());
            EXPECT_EQ(in_place, want_right) << "degree " << n << ", right half in place";
            EXPECT_EQ(left, want_left) << "degree " << n << ", left half beside it";
            in_place = b;
            std::fill(right.begin(), right.end(), 0.0);
            split_bernstein(in_place.data(), n, in_place.data(), right.data());
            EXPECT_EQ(in_place, want_left) << "degree " << n << ", left half in place";
            EXPECT_EQ(right, want_right) << "degree " << n << ", right half beside it";
        }
    }
}

}  // namespace
}  // namespace zeroset
