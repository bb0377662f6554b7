// The guarded first hit by Bernstein subdivision
// (roots/subdivided_first_root.hpp) against the scan over F̂'s extrema
// (roots/polynomial_enclosure.hpp) that it replaces in the polynomial method.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "root_test_support.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"
#include "zeroset/roots/polynomial_roots.hpp"
#include "zeroset/roots/subdivided_first_root.hpp"

namespace zeroset {
namespace {

PossibleRoot by_extrema(PolynomialEnclosure f, double t0, double t1) {
    std::array<double, max_polynomial_degree> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(f.value, t0, t1, extrema);
    return first_possible_root(f, t0, t1, std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)),
                               false);
}

/// ∏ (t − rᵢ) · scale, plus `lift`: real roots where wanted, or a dip.
std::vector<double> with_roots(const std::vector<double>& roots, double scale, double lift) {
    std::vector<double> p = test::from_roots(roots, scale);
    p[0] += lift;
    return p;
}

TEST(SubdividedFirstRoot, AgreesWithTheScanOverExtrema) {
    // Polynomials of degree 2 to 10 with roots, clusters and near-tangent
    // dips in and around the span, and a radius from none to loose. The two
    // guards may differ only where the scan's bound is looser (it takes R at
    // the farther end of a whole monotone piece, the subdivision at the
    // farther end of a small piece) and where the signs prove a crossing
    // simple. So: whatever this one finds the scan finds; a crossing the
    // scan finds this one finds too; what it reports is a possible root,
    // not after the scan's.
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> place(-2.0, 2.0);
    std::uniform_int_distribution<int> degree(2, 10);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int crossings = 0, grazes = 0, grazes_kept = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const int n = degree(random);
        std::vector<double> roots;
        for (int i = 0; i < n; ++i) roots.push_back(place(random));
        if (unit(random) < 0.3) roots[1] = roots[0] + 1e-9 * place(random);  // a cluster or near-double root
        const double lift = unit(random) < 0.3 ? std::pow(10.0, -16.0 * unit(random)) : 0.0;
        const std::vector<double> p = with_roots(roots, unit(random) < 0.5 ? 1.0 : -1.0, lift);
        std::vector<double> radius(p.size(), 0.0);
        radius[0] = unit(random) < 0.3 ? 0.0 : std::pow(10.0, -6.0 - 10.0 * unit(random));
        const PolynomialEnclosure f{p, radius};
        const double t0 = -2.5 + unit(random), t1 = 1.5 + unit(random);
        if (horner(p, t0).value <= 0.0) continue;  // the method starts outside
        const PossibleRoot old = by_extrema(f, t0, t1);
        const PossibleRoot now = first_possible_root_subdividing(f, t0, t1);
        if (now.found) {
            ASSERT_TRUE(old.found) << "trial " << trial;
        }
        if (old.sign_change) {
            ++crossings;
            ASSERT_TRUE(now.found) << "trial " << trial;
        }
        if (old.found && !old.sign_change) ++grazes, grazes_kept += now.found;
        if (!now.found) {
            // Clear where the scan saw a graze: F̂ stays above R at each of
            // its turns, where a dip comes closest.
            std::array<double, max_polynomial_degree> extrema{};
            const PolynomialRoots e = fast_polynomial_extrema(p, t0, t1, extrema);
            for (int i = 0; i < e.count; ++i) {
                const double t = extrema[static_cast<std::size_t>(i)];
                EXPECT_GT(horner(p, t).value, enclosure_bound(f, t)) << "trial " << trial << ", t = " << t;
            }
            continue;
        }
        // A possible root indeed: F̂ within the bound on the span of 0 there
        // (a root of F̂, or a graze placed where F̂ reaches a piece's bound;
        // twice the bound allows for the rounding of placing it on a
        // cluster's flat bottom).
        const double span_bound = enclosure_bound(f, std::max(-t0, t1));
        const auto uncertain = [&](double t) { return std::abs(horner(p, t).value) <= 2.0 * span_bound; };
        EXPECT_TRUE(uncertain(now.t)) << "trial " << trial;
        // Not after the scan's crossing, unless both lie in one zone where F̂
        // is within rounding of 0 (a cluster's roots). (After its graze where
        // the tighter bound proves F clear there.)
        if (old.sign_change && now.t > old.t + 1e-12 * (1.0 + std::abs(old.t))) {
            EXPECT_TRUE(uncertain(old.t) && now.t - old.t < 1e-6) << "trial " << trial;
        }
    }
    EXPECT_GT(crossings, 5000);  // the cases are all exercised
    EXPECT_GT(grazes, 200);
    EXPECT_GT(grazes_kept, grazes / 2);
}

TEST(SubdividedFirstRoot, ADipWithinTheBoundIsAHitAndOneBeyondItIsNot) {
    // (t − 1)² + depth on [0, 3], F known to within 1e-11.
    const std::vector<double> radius{1e-11, 0.0, 0.0};
    const std::vector<double> shallow{1.0 + 1e-12, -2.0, 1.0};
    const PossibleRoot graze = first_possible_root_subdividing({shallow, radius}, 0.0, 3.0);
    ASSERT_TRUE(graze.found);
    EXPECT_FALSE(graze.sign_change);
    EXPECT_NEAR(graze.t, 1.0, 1e-5);
    EXPECT_LE(graze.t, 1.0);
    const std::vector<double> deep{1.0 + 1e-9, -2.0, 1.0};
    EXPECT_FALSE(first_possible_root_subdividing({deep, radius}, 0.0, 3.0).found);
}

TEST(SubdividedFirstRoot, ACrossingIsTheRootOfTheRoundedPolynomial) {
    const std::vector<double> p{0.75, -2.0, 1.0};  // roots 0.5 and 1.5
    const std::vector<double> radius{1e-11, 0.0, 0.0};
    const PossibleRoot r = first_possible_root_subdividing({p, radius}, 0.0, 3.0);
    ASSERT_TRUE(r.found);
    EXPECT_TRUE(r.sign_change);
    EXPECT_NEAR(r.t, 0.5, 1e-15);
    // The start, the conversion, a split and the closed form with its
    // polish: the piece's end values are its end coefficients, beyond the
    // bound, and are not evaluated again (7 evaluations when they were).
    EXPECT_LE(r.evaluations, 5);
}

TEST(SubdividedFirstRoot, CoefficientsAboveZeroButWithinTheBoundProveNothing) {
    // d + t⁴ on [−h, h] with h⁴ = 5e-12, d = 6e-12, F known to within 1e-11:
    // its Bernstein coefficients d ± h⁴ are all positive, but F̂ dips to d,
    // below the bound, so F may vanish at 0; F̂(−h) = 1.1e-11 is above it.
    const double h = std::pow(5e-12, 0.25);
    const std::vector<double> p{6e-12, 0.0, 0.0, 0.0, 1.0};
    const std::vector<double> radius{1e-11, 0.0, 0.0, 0.0, 0.0};
    ASSERT_GT(horner(p, -h).value, enclosure_bound({p, radius}, -h));
    const PossibleRoot r = first_possible_root_subdividing({p, radius}, -h, h);
    ASSERT_TRUE(r.found);
    EXPECT_FALSE(r.sign_change);
    EXPECT_LT(r.t, 0.0);
    EXPECT_LE(horner(p, r.t).value, 1.01 * enclosure_bound({p, radius}, -h));
}

}  // namespace
}  // namespace zeroset
