// The guarded first hit of a polynomial known only to within a bound
// (roots/polynomial_enclosure.hpp), the extrema of the fast solver, and the
// bracketed Newton that both rely on (roots/monotone_pieces.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/monotone_pieces.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"
#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {
namespace {

/// (t − 1)² + depth: a dip towards 0 at t = 1 whose bottom is `depth` above it.
std::vector<double> dip(double depth) { return {1.0 + depth, -2.0, 1.0}; }

PossibleRoot first(const std::vector<double>& value, double radius0, double t0, double t1) {
    const std::vector<double> radius{radius0, 0.0, 0.0};
    std::array<double, 2> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(value, t0, t1, extrema);
    return first_possible_root({value, radius}, t0, t1,
                               std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)), false);
}

/// possible_roots over [t0, t1] with a constant radius.
std::vector<double> all_possible(const std::vector<double>& value, double radius0, double t0, double t1) {
    const std::vector<double> radius(value.size(), 0.0);
    std::vector<double> r = radius;
    r[0] = radius0;
    std::array<double, 8> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(value, t0, t1, extrema);
    std::array<double, 8> out{};
    int evaluations = 0;
    const int n = possible_roots({value, r}, t0, t1,
                                 std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)), out,
                                 evaluations);
    return {out.begin(), out.begin() + n};
}

TEST(PolynomialEnclosure, AllPossibleRootsIncludeGrazesBetweenCrossings) {
    // (t − 0.5)(t − 3.5)·((t − 2)² + 1e-12): crossings at 0.5 and 3.5 and,
    // between them, a dip at 2 that the bound cannot tell from a double root.
    const std::vector<double> crossings{1.75, -4.0, 1.0};  // (t − 0.5)(t − 3.5)
    const std::vector<double> dip_at_2{4.0 + 1e-12, -4.0, 1.0};
    std::vector<double> p(5, 0.0);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) p[i + j] += crossings[i] * dip_at_2[j];
    const std::vector<double> roots = all_possible(p, 1e-10, 0.0, 5.0);
    ASSERT_EQ(roots.size(), 3u);
    EXPECT_NEAR(roots[0], 0.5, 1e-12);
    EXPECT_NEAR(roots[1], 2.0, 1e-5);
    EXPECT_NEAR(roots[2], 3.5, 1e-12);
    // With no rounding to fear, the dip is no root.
    EXPECT_EQ(all_possible(p, 0.0, 0.0, 5.0).size(), 2u);
}

TEST(PolynomialEnclosure, ADipShallowerThanTheBoundIsAHit) {
    // F̂ stays 1e-12 above 0, but F may be anywhere within 1e-11 of F̂.
    const PossibleRoot r = first(dip(1e-12), 1e-11, 0.0, 3.0);
    ASSERT_TRUE(r.found);
    EXPECT_FALSE(r.sign_change);
    // The first t where F̂ comes within the bound: no root of F lies before it.
    EXPECT_LE(r.t, 1.0);
    EXPECT_GT(r.t, 1.0 - 1e-5);
    EXPECT_LE(std::abs(horner(dip(1e-12), r.t).value), 1.1e-11);
}

TEST(PolynomialEnclosure, ADipDeeperThanTheBoundIsNoHit) {
    EXPECT_FALSE(first(dip(1e-9), 1e-11, 0.0, 3.0).found);
    EXPECT_FALSE(first(dip(1e-12), 0.0, 0.0, 3.0).found);
}

TEST(PolynomialEnclosure, ACrossingIsRefinedToTheRootOfTheRoundedPolynomial) {
    const PossibleRoot r = first(dip(-0.25), 1e-11, 0.0, 3.0);  // roots 0.5 and 1.5
    ASSERT_TRUE(r.found);
    EXPECT_TRUE(r.sign_change);
    EXPECT_NEAR(r.t, 0.5, 1e-15);
}

TEST(PolynomialEnclosure, AStartWithinTheBoundIsAHitThere) {
    const PossibleRoot r = first({1e-12, 1.0, 0.0}, 1e-11, 0.0, 1.0);
    ASSERT_TRUE(r.found);
    EXPECT_EQ(r.t, 0.0);
}

TEST(PolynomialEnclosure, AKnownRootIsKeptUnlessADipComesFirst) {
    // p = ((t − 1)² + 1e-12)·(2 − t): a dip of depth 1e-12 at 1, then a
    // crossing at 2. The scan stops short of a root already known at 1.9.
    const std::vector<double> p{2.0 + 2e-12, -5.0 - 1e-12, 4.0, -1.0};
    std::array<double, 2> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(p, 0.0, 1.9, extrema);
    const std::span<const double> ex(extrema.data(), static_cast<std::size_t>(e.count));
    const std::vector<double> tight{0.0, 0.0, 0.0, 0.0};
    const std::vector<double> loose{1e-11, 0.0, 0.0, 0.0};
    // With no error the dip holds no root: the known root (pretend 1.9) stands.
    const PossibleRoot kept = first_possible_root({p, tight}, 0.0, 1.9, ex, true);
    ASSERT_TRUE(kept.found);
    EXPECT_EQ(kept.t, 1.9);
    // With an error larger than the dip's depth the dip comes first.
    const PossibleRoot dip_first = first_possible_root({p, loose}, 0.0, 1.9, ex, true);
    ASSERT_TRUE(dip_first.found);
    EXPECT_NEAR(dip_first.t, 1.0, 1e-5);
}

TEST(PolynomialEnclosure, TheBoundGrowsWithTheDistanceFromTheCentre) {
    const std::vector<double> value{1.0, 0.0, 1.0};
    const std::vector<double> radius{1e-16, 0.0, 1e-16};
    const double near = enclosure_bound({value, radius}, 0.0);
    const double far = enclosure_bound({value, radius}, -10.0);
    EXPECT_GE(near, 1e-16);
    EXPECT_GT(far, 100.0 * 1e-16);
    EXPECT_EQ(far, enclosure_bound({value, radius}, 10.0));
}

/// (t − r₁)…(t − r_n)·scale, its roots spread over several orders of
/// magnitude, with radii 10⁻¹² to 10⁻⁸ of its coefficients.
struct RandomEnclosure {
    std::vector<double> value, radius;
    double farthest = 0.0;  // the largest |root|
};

RandomEnclosure random_enclosure(std::mt19937& random, int degree) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    RandomEnclosure e;
    e.value = {std::pow(10.0, 3.0 * u(random))};
    for (int k = 0; k < degree; ++k) {
        const double root = u(random) * std::pow(10.0, 2.0 * u(random));
        e.farthest = std::max(e.farthest, std::abs(root));
        std::vector<double> next(e.value.size() + 1, 0.0);
        for (std::size_t i = 0; i < e.value.size(); ++i) {
            next[i + 1] += e.value[i];
            next[i] -= root * e.value[i];
        }
        e.value = next;
    }
    e.radius.resize(e.value.size());
    for (std::size_t i = 0; i < e.value.size(); ++i) e.radius[i] = std::abs(e.value[i]) * std::pow(10.0, -12.0 + 4.0 * u(random));
    return e;
}

/// F̂(t) and Σ rᵢ|t|ⁱ: where |F̂| exceeds the second, no F within the radii vanishes.
std::pair<double, double> value_and_radius_at(const RandomEnclosure& e, double t) {
    double fhat = 0.0, r = 0.0;
    for (std::size_t i = e.value.size(); i-- > 0;) {
        fhat = fhat * t + e.value[i];
        r = r * std::abs(t) + e.radius[i];
    }
    return {fhat, r};
}

TEST(PolynomialEnclosure, NoPolynomialWithinTheRadiusVanishesBeyondTheRootRadius) {
    std::mt19937 random(7);
    int cut = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const RandomEnclosure e = random_enclosure(random, 1 + trial % 6);
        const double within = 1e6;
        const double rho = root_radius({e.value, e.radius}, within, within);
        if (!std::isfinite(rho)) continue;
        ++cut;
        EXPECT_GE(rho, e.farthest) << "trial " << trial;  // F̂'s own roots lie inside
        // Beyond ρ, |F̂| exceeds what the radius allows F to differ by: no root of F.
        for (const double beyond : {1.0, 1.001, 1.5, 4.0, 1e3}) {
            for (const double t : {rho * beyond, -rho * beyond}) {
                const auto [fhat, r] = value_and_radius_at(e, t);
                EXPECT_GT(std::abs(fhat), r) << "trial " << trial << " t " << t;
            }
        }
    }
    EXPECT_GT(cut, 1500);  // the bound cuts nearly every such span
}

// The radius is the least of the grid largest·2^−j that bounds: within a
// factor 2 of Fujiwara's 2·max_k (w_(n−k)/lead)^(1/k), w being a
// coefficient's weight with its radius, and the same whatever power-of-two
// multiple of itself `largest` is (a faster search for it must end where
// the halvings do).
TEST(PolynomialEnclosure, TheRootRadiusIsWithinTwiceFujiwarasAndOnItsGrid) {
    std::mt19937 random(13);
    std::uniform_int_distribution<int> shift(0, 6);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const RandomEnclosure e = random_enclosure(random, 1 + trial % 6);
        const std::size_t n = e.value.size() - 1;
        const double lead = std::abs(e.value[n]) - e.radius[n];
        double fujiwara = 0.0;
        for (std::size_t k = 1; k <= n; ++k)
            fujiwara = std::max(fujiwara, 2.0 * std::pow((std::abs(e.value[n - k]) + e.radius[n - k]) / lead, 1.0 / static_cast<double>(k)));
        const double largest = 1e6;
        const double rho = root_radius({e.value, e.radius}, largest, largest);
        if (!std::isfinite(rho)) continue;
        ++checked;
        EXPECT_GE(rho, fujiwara * (1.0 - 1e-12)) << "trial " << trial;
        EXPECT_LE(rho, 2.0 * fujiwara * (1.0 + 1e-12)) << "trial " << trial;
        const double finer = largest / std::ldexp(1.0, shift(random));
        if (finer >= rho) {
            EXPECT_EQ(root_radius({e.value, e.radius}, largest, finer), rho) << "trial " << trial;
        }
    }
    EXPECT_GT(checked, 1500);
}

// The same with a top coefficient that may be 0 (a ray along which the top
// form nearly vanishes): the next one leads, and only up to the reach given.
TEST(PolynomialEnclosure, NoPolynomialVanishesBeyondTheRootRadiusWhenTheTopCoefficientMayBeZero) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int cut = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        RandomEnclosure e = random_enclosure(random, 1 + trial % 5);
        // A top coefficient far below the rest, and its radius above it.
        const double top = e.value.back() * std::pow(10.0, -8.0 + 6.0 * u(random));
        e.value.push_back(top);
        e.radius.push_back(std::abs(top) * (1.0 + std::abs(u(random))));
        const double within = std::pow(10.0, 2.0 + 2.0 * std::abs(u(random)));
        const double rho = root_radius({e.value, e.radius}, within, within);
        if (!std::isfinite(rho)) continue;
        ++cut;
        // Any polynomial within the radii keeps clear of 0 from ρ to the reach.
        for (double t = rho; t <= within; t *= 1.07) {
            for (const double at : {t, -t}) {
                const auto [fhat, r] = value_and_radius_at(e, at);
                EXPECT_GT(std::abs(fhat), r) << "trial " << trial << " t " << at;
            }
        }
    }
    EXPECT_GT(cut, 500);  // the lower coefficient leads on many such spans
}

TEST(PolynomialEnclosure, TheRootRadiusCutsNothingItCannotProve) {
    const std::vector<double> value{-4.0, 0.0, 1.0};  // roots ±2
    EXPECT_EQ(root_radius({value, std::vector<double>{0.0, 0.0, 1.0}}, 1e6, 1e6), std::numeric_limits<double>::infinity())
        << "the leading coefficient may be 0";
    EXPECT_EQ(root_radius({value, std::vector<double>{0.0, 0.0, 0.0}}, 3.0, 3.0), std::numeric_limits<double>::infinity())
        << "the bound (here 4) is no nearer than the span's ends";
    const double rho = root_radius({value, std::vector<double>{0.0, 0.0, 0.0}}, 1e6, 1e6);
    EXPECT_GE(rho, 4.0);  // Fujiwara's bound, 2·√4
    EXPECT_LE(rho, 8.0);  // found by halving: within a factor 2 of it
    EXPECT_EQ(root_radius({std::vector<double>{3.0}, std::vector<double>{0.0}}, 1e6, 1e6), std::numeric_limits<double>::infinity());
}

// A ray along which the top form vanishes (steiner's along its axes): the
// cubic coefficient is 0 to within its radius, and the quadratic leads up to
// the span's reach.
TEST(PolynomialEnclosure, TheRootRadiusLetsALowerTermLeadWhereTheTopOneMayVanish) {
    const std::vector<double> value{-2.0, 1.0, 1.0, 1e-20};  // ≈ (t − 1)(t + 2)
    const std::vector<double> radius{0.0, 0.0, 0.0, 2e-20};
    const double within = 1e4;
    EXPECT_EQ(root_radius({value, radius}, within, 2.0), std::numeric_limits<double>::infinity())
        << "no bound below 2·√2 exists";
    const double rho = root_radius({value, radius}, within, within);
    EXPECT_GE(rho, 2.0 * std::sqrt(2.0));
    EXPECT_LE(rho, 4.0 * std::sqrt(2.0));
    // Every polynomial within the radii keeps its sign from ρ to the reach.
    for (const double top : {-1e-20, 0.0, 3e-20}) {
        for (double t = rho; t <= within; t *= 1.1) {
            for (const double at : {t, -t}) EXPECT_GT(-2.0 + at + at * at + top * at * at * at, 0.0) << "t " << at;
        }
    }
    EXPECT_EQ(root_radius({value, radius}, 1e21, 1e21), std::numeric_limits<double>::infinity())
        << "over a reach where the cubic term may outweigh the quadratic, nothing leads";
}

TEST(FastPolynomialExtrema, AreTheRootsOfTheDerivative) {
    // p = (t − 0.1)(t − 0.5)(t − 0.9)(t − 2): p′ has three real roots.
    const std::vector<double> p{0.09, -1.225, 3.59, -3.5, 1.0};
    std::array<double, 3> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(p, -1.0, 3.0, extrema);
    ASSERT_EQ(e.count, 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(std::abs(horner(p, extrema[static_cast<std::size_t>(i)]).derivative), 1e-12);
        if (i > 0) {
            EXPECT_LT(extrema[static_cast<std::size_t>(i - 1)], extrema[static_cast<std::size_t>(i)]);
        }
    }
    std::array<double, 1> one{};
    EXPECT_EQ(fast_polynomial_extrema(std::vector<double>{1.0, -2.0, 1.0}, 0.0, 3.0, one).count, 1);
    EXPECT_NEAR(one[0], 1.0, 1e-15);
}

TEST(MonotoneRoot, NearADoubleRootDoesNotStepAway) {
    // A Barth sextic ray that grazes the surface: on this piece p falls from
    // 17.5 to −1e-14 at a near-double root, where p′ is nearly 0 too. A last
    // Newton step there used to jump 0.19 back up the slope (p ≈ 2.9).
    const std::vector<double> p{23.44657406655692, 58.44921681218639, 0.7434995108854086, -56.703111903676614,
                                0.4004775779656309, 12.879223771661298, 1.989936009381907};
    const PolynomialSample lo = sample_polynomial(p, -1.0815348894041241);
    const PolynomialSample hi = sample_polynomial(p, -0.62109439187144189);
    ASSERT_GT(lo.value, 0.0);
    int evaluations = 0;
    const double t = monotone_root(p, lo, hi, evaluations);
    EXPECT_LE(std::abs(horner(p, t).value), 1e-9);
    EXPECT_NEAR(t, -0.621094, 1e-5);
}

TEST(MonotoneRoot, ATolerancePlacesTheRootWithinItForFewerEvaluations) {
    // (t − r)·(t² + 1)·(t + 3): one root r in [−1, 2], where p rises. With a
    // tolerance of 10⁻¹⁰ of the bracket the root is as good (Newton's last
    // error is about its step squared) and the polishing steps are saved.
    int full = 0, tolerant = 0;
    for (int i = 0; i < 200; ++i) {
        const double r = -0.9 + 2.8 * i / 200.0;
        // (t − r)(t + 3) = t² + (3 − r)t − 3r; times (t² + 1).
        const std::vector<double> p{-3.0 * r, 3.0 - r, 1.0 - 3.0 * r, 3.0 - r, 1.0};
        const PolynomialSample lo = sample_polynomial(p, -1.0), hi = sample_polynomial(p, 2.0);
        ASSERT_LT(lo.value, 0.0);
        ASSERT_GT(hi.value, 0.0);
        const double exact = monotone_root(p, lo, hi, full);
        const double close = monotone_root(p, lo, hi, tolerant, 1e-10 * 3.0);
        EXPECT_NEAR(exact, r, 1e-14) << r;
        EXPECT_NEAR(close, r, 1e-10 * 3.0) << r;
    }
    EXPECT_LT(tolerant, full);
}

TEST(MonotoneRoot, AFirstGuessNearTheRootSavesEvaluationsAndOneOutsideIsIgnored) {
    // The same pieces as above: a guess within 1 % of the bracket from the
    // root (as a control polygon's crossing gives) ends at the same root;
    // a guess outside the bracket (or NaN) leaves the secant start.
    int secant = 0, guessed = 0, ignored = 0;
    for (int i = 0; i < 200; ++i) {
        const double r = -0.9 + 2.8 * i / 200.0;
        const std::vector<double> p{-3.0 * r, 3.0 - r, 1.0 - 3.0 * r, 3.0 - r, 1.0};
        const PolynomialSample lo = sample_polynomial(p, -1.0), hi = sample_polynomial(p, 2.0);
        const double from_secant = monotone_root(p, lo, hi, secant);
        EXPECT_NEAR(monotone_root(p, lo, hi, guessed, 0.0, r + 0.03), from_secant, 4e-16) << r;
        int outside = 0;
        EXPECT_EQ(monotone_root(p, lo, hi, outside, 0.0, 5.0), from_secant) << r;
        ignored += outside;
    }
    EXPECT_LT(guessed, secant);
    EXPECT_EQ(ignored, secant);
}

TEST(PolynomialEnclosure, APositiveSpanIsProvenByItsBernsteinCoefficients) {
    const std::vector<double> radius{1e-11, 0.0, 0.0};
    // (t − 1)² + depth: on [0, 3] the Bernstein coefficients are 1 + d,
    // d − 2, 4 + d, so a dip 3 deep is proven and one 0.5 deep is not (false
    // proves nothing); near the dip's bottom they tighten to its depth.
    EXPECT_TRUE(provably_positive({dip(3.0), radius}, 0.0, 3.0));
    EXPECT_FALSE(provably_positive({dip(0.5), radius}, 0.0, 3.0));
    EXPECT_TRUE(provably_positive({dip(1e-9), radius}, 1.0 - 1e-5, 1.0 + 1e-5));
    // A dip shallower than the radius is never proven, nor is a crossing.
    EXPECT_FALSE(provably_positive({dip(1e-12), radius}, 1.0 - 1e-7, 1.0 + 1e-7));
    EXPECT_FALSE(provably_positive({dip(-0.25), radius}, 0.0, 3.0));
    // A span that stops short of the roots 0.5 and 1.5 is proven.
    EXPECT_TRUE(provably_positive({dip(-0.25), radius}, -2.0, 0.4));
}

TEST(PolynomialEnclosure, WhatIsProvenPositiveHasNoPossibleRoot) {
    // Random quartics about 0, their spans, and a radius: wherever the
    // Bernstein test says F > 0, the guarded scan finds no possible root
    // and F̂ stays above the bound at a fine sampling.
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    std::uniform_real_distribution<double> half_width(0.1, 3.0);
    int proven = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        std::vector<double> value(5);
        for (double& c : value) c = coefficient(random);
        value[0] = std::abs(value[0]) + 0.01;  // outside at the centre
        const std::vector<double> radius{1e-3 * std::abs(coefficient(random)), 0.0, 0.0, 0.0, 0.0};
        const double s0 = -half_width(random), s1 = half_width(random);
        if (!provably_positive({value, radius}, s0, s1)) continue;
        ++proven;
        std::array<double, 4> extrema{};
        const PolynomialRoots e = fast_polynomial_extrema(value, s0, s1, extrema);
        EXPECT_FALSE(first_possible_root({value, radius}, s0, s1,
                                         std::span<const double>(extrema.data(), static_cast<std::size_t>(e.count)), false)
                         .found);
        for (int i = 0; i <= 1000; ++i) {
            const double s = s0 + (s1 - s0) * i / 1000.0;
            ASSERT_GT(horner(value, s).value, enclosure_bound({value, radius}, s)) << "trial " << trial << ", s = " << s;
        }
    }
    EXPECT_GT(proven, 200);  // the test is exercised
    EXPECT_LT(proven, 4000);
}

}  // namespace
}  // namespace zeroset
