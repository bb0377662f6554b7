// The closed forms on the cases that break naive formulas: roots of very
// different magnitude, multiple and nearly equal roots, zero roots, a
// vanishing leading coefficient, clustered and complex quartic roots.
// References are the known roots (exact in double) or long double products.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "zeroset/roots/closed_form.hpp"

namespace zeroset {
namespace {

/// Ascending coefficients of lead·∏(t − rᵢ), expanded in long double.
std::vector<double> from_roots(const std::vector<long double>& r, long double lead = 1.0L) {
    std::vector<long double> c{lead};
    for (const long double root : r) {
        std::vector<long double> next(c.size() + 1, 0.0L);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= root * c[i];
        }
        c = next;
    }
    return {c.begin(), c.end()};
}

std::vector<double> solve(const std::vector<double>& c) {
    std::array<double, max_closed_form_degree> roots{};
    const int n = solve_closed_form(c, roots);
    return {roots.begin(), roots.begin() + n};
}

void expect_roots(const std::vector<double>& c, const std::vector<double>& expected, double rel) {
    const std::vector<double> got = solve(c);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        EXPECT_LE(std::fabs(got[i] - expected[i]), rel * std::max(1e-300, std::fabs(expected[i])))
            << i << ": " << got[i] << " vs " << expected[i];
}

TEST(ClosedForm, QuadraticWithoutCancellation) {
    // Roots 1e-9 and 1e9: the textbook formula loses the small one entirely.
    expect_roots({1.0, -(1e9 + 1e-9), 1.0}, {1e-9, 1e9}, 1e-15);
    expect_roots({-2.0, 0.0, 1.0}, {-std::sqrt(2.0), std::sqrt(2.0)}, 2e-16);
    expect_roots({1.0, 0.0, 1.0}, {}, 0.0);
    expect_roots({1.0, -2.0, 1.0}, {1.0}, 0.0);  // a double root, reported once
    expect_roots({1e300, -3e300, 2e300}, {0.5, 1.0}, 1e-15);  // squares would overflow unscaled
}

TEST(ClosedForm, NearlyEqualQuadraticRoots) {
    // (t − 1)(t − (1 + 2⁻²⁰)): the fma-corrected discriminant still separates them.
    const double r2 = 1.0 + std::ldexp(1.0, -20);
    expect_roots(from_roots({1.0L, static_cast<long double>(r2)}), {1.0, r2}, 1e-12);
}

TEST(ClosedForm, ZeroRootsAndDegreeDrops) {
    expect_roots({0.0, -3.0, 1.0}, {0.0, 3.0}, 1e-16);
    expect_roots({0.0, 0.0, 0.0, 2.0, 1.0}, {-2.0, 0.0}, 1e-16);
    expect_roots({-6.0, 2.0, 0.0}, {3.0}, 0.0);          // leading 0: linear
    expect_roots({2.0, -3.0, 1.0, 0.0, 0.0}, {1.0, 2.0}, 1e-15);  // quartic slot, quadratic content
    expect_roots({2.0, -3.0, 1.0, 1e-30}, {1.0, 2.0}, 1e-15);     // tiny leading: dropped
    expect_roots({0.0, 0.0, 0.0}, {}, 0.0);                       // identically zero
    // A small but genuine leading coefficient is kept: its far root comes out.
    expect_roots(from_roots({1.0L, 2.0L, 1e6L}, 1e-6L), {1.0, 2.0, 1e6}, 1e-12);
}

TEST(ClosedForm, CubicRoots) {
    expect_roots(from_roots({-1.0L, 2.0L, 3.0L}), {-1.0, 2.0, 3.0}, 1e-15);
    expect_roots(from_roots({1e-4L, 1.0L, 1e4L}), {1e-4, 1.0, 1e4}, 1e-13);
    expect_roots({-1.0, 0.0, 0.0, 1.0}, {1.0}, 1e-16);   // t³ = 1
    expect_roots({1.0, 1.0, 0.0, 1.0}, {-0.68232780382801939}, 1e-15);  // one real
    expect_roots({0.0, -1.0, 0.0, 1.0}, {-1.0, 0.0, 1.0}, 1e-16);
}

TEST(ClosedForm, CubicMultipleRoots) {
    // (t − 1)²(t − 2): the double root is sensitive (√ε), the simple one is not.
    std::vector<double> got = solve({-2.0, 5.0, -4.0, 1.0});
    ASSERT_GE(got.size(), 2u);
    EXPECT_NEAR(got.front(), 1.0, 1e-7);
    EXPECT_NEAR(got.back(), 2.0, 1e-15);
    // (t − 1)³: a triple root, accurate to ε^(1/3).
    got = solve({-1.0, 3.0, -3.0, 1.0});
    ASSERT_FALSE(got.empty());
    for (const double r : got) EXPECT_NEAR(r, 1.0, 1e-5);
}

TEST(ClosedForm, QuarticRoots) {
    expect_roots(from_roots({-3.0L, -1.0L, 0.5L, 2.0L}), {-3.0, -1.0, 0.5, 2.0}, 1e-14);
    expect_roots(from_roots({-2.0L, 2.0L, -1.0L, 1.0L}), {-2.0, -1.0, 1.0, 2.0}, 1e-15);  // biquadratic
    expect_roots({4.0, 0.0, 5.0, 0.0, 1.0}, {}, 0.0);  // (t² + 1)(t² + 4)
    // (t² + 2t + 5)(t² − 2t + 2): complex only, not biquadratic.
    expect_roots({10.0, -6.0, 3.0, 0.0, 1.0}, {}, 0.0);
    // Two real roots and a complex pair: (t − 1)(t + 3)(t² + t + 1).
    expect_roots({-3.0, -1.0, 0.0, 3.0, 1.0}, {-3.0, 1.0}, 1e-15);
    expect_roots(from_roots({1e-3L, 1.0L, 10.0L, 1e3L}), {1e-3, 1.0, 10.0, 1e3}, 1e-12);
}

TEST(ClosedForm, ClusteredQuarticRoots) {
    // Four roots within 3e-3: each is known only to about ε/(gap³) ≈ 1e-8.
    const std::vector<double> expected{1.0, 1.001, 1.002, 1.003};
    const std::vector<double> got = solve(from_roots({1.0L, 1.001L, 1.002L, 1.003L}));
    ASSERT_EQ(got.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(got[i], expected[i], 1e-6) << i;
}

TEST(ClosedForm, TorusAlongARay) {
    // Torus R = 1, r = 0.25 along the x axis at height y = z = 0: hits at
    // t − 3 = ±0.75, ±1.25 → t = 1.75, 2.25, 3.75, 4.25.
    expect_roots(from_roots({1.75L, 2.25L, 3.75L, 4.25L}), {1.75, 2.25, 3.75, 4.25}, 1e-15);
}

TEST(ClosedForm, RootsInRange) {
    const std::vector<double> c = from_roots({-1.0L, 0.5L, 2.0L, 3.0L});
    std::array<double, max_closed_form_degree> roots{};
    ASSERT_EQ(closed_form_roots_in(c, 0.0, 2.5, roots), 2);
    EXPECT_NEAR(roots[0], 0.5, 1e-15);
    EXPECT_NEAR(roots[1], 2.0, 1e-15);
    EXPECT_EQ(closed_form_roots_in(c, 3.5, 10.0, roots), 0);
    ASSERT_TRUE(closed_form_first_root(c, 1.0, 10.0));
    EXPECT_NEAR(*closed_form_first_root(c, 1.0, 10.0), 2.0, 1e-15);
    EXPECT_FALSE(closed_form_first_root(c, 3.5, 10.0));
    // The survey's eq. 10: F(t) = 1.00024084 t² − 12.1476884 t + 36.852421.
    const auto hit = closed_form_first_root(std::vector{36.852421, -12.1476884, 1.00024084}, 0.0, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(1.00024084 * *hit * *hit - 12.1476884 * *hit + 36.852421, 0.0, 1e-12);
}

TEST(ClosedForm, NewtonPolishReachesFullPrecision) {
    // Random well-separated roots: relative error ≲ 1e-12 after the polish.
    unsigned state = 12345;
    const auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<double>(state >> 8) / static_cast<double>(1u << 24) * 20.0 - 10.0;
    };
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<long double> r;
        const int n = 2 + trial % 3;
        for (int i = 0; i < n; ++i) r.push_back(static_cast<long double>(next()));
        std::sort(r.begin(), r.end());
        bool separated = true;
        for (int i = 1; i < n; ++i) separated = separated && (r[i] - r[i - 1] > 0.5L);
        if (!separated) continue;
        const std::vector<double> got = solve(from_roots(r, 0.7L));
        ASSERT_EQ(got.size(), r.size()) << trial;
        for (int i = 0; i < n; ++i) {
            const double want = static_cast<double>(r[i]);
            EXPECT_LE(std::fabs(got[i] - want), 1e-12 * std::max(1.0, std::fabs(want))) << trial << " " << i;
        }
    }
}

}  // namespace
}  // namespace zeroset
