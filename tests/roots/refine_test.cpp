// refine_root: safeguarded Newton on a bracket. Quadratic on simple roots
// (a few evaluations where bisection needs fifty), the bracket closed to
// adjacent doubles from both sides, multiple roots jumped to, and no worse
// than bisection when H′ misleads.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "root_test_support.hpp"
#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/refine.hpp"

namespace zeroset {
namespace {

TEST(RefineRoot, SimpleRootsTakeAFewEvaluations) {
    for (const test::KnownRoot& k : test::known_roots()) {
        if (!k.simple) continue;
        SCOPED_TRACE(k.name);
        auto h = test::counted([&k](double t) { return k.both(t); });
        const BracketResult r = refine_root(h, k.a, k.b);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, k.root), 1);
        EXPECT_EQ(h.calls, r.evaluations);
        EXPECT_LE(r.evaluations, 12);
    }
}

TEST(RefineRoot, EndsAlreadyEvaluatedAreNotEvaluatedAgain) {
    for (const test::KnownRoot& k : test::known_roots()) {
        SCOPED_TRACE(k.name);
        auto fresh = test::counted([&k](double t) { return k.both(t); });
        const BracketResult from_scratch = refine_root(fresh, k.a, k.b);
        auto h = test::counted([&k](double t) { return k.both(t); });
        const BracketResult r = refine_root(h, BracketPoint{k.a, k.both(k.a)}, BracketPoint{k.b, k.both(k.b)});
        EXPECT_EQ(r.status, from_scratch.status);
        EXPECT_EQ(r.t, from_scratch.t);  // the same steps, two evaluations fewer
        EXPECT_EQ(h.calls, fresh.calls - 2);
    }
}

TEST(RefineRoot, EndsKnownByTheirValueAloneStartWithRegulaFalsi) {
    // Ends given with H alone (H′ NaN, as a march that just found the
    // bracket knows them): the first step is the secant's, then Newton; on
    // every simple root the same root as from scratch, for no more
    // evaluations of H and H′ than from scratch, whose ends cost two.
    for (const test::KnownRoot& k : test::known_roots()) {
        if (!k.simple) continue;
        SCOPED_TRACE(k.name);
        constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
        auto h = test::counted([&k](double t) { return k.both(t); });
        const BracketResult r = refine_root(h, BracketPoint{k.a, {k.both(k.a).value, unknown}},
                                            BracketPoint{k.b, {k.both(k.b).value, unknown}});
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, k.root), 1);
        auto fresh = test::counted([&k](double t) { return k.both(t); });
        EXPECT_LE(h.calls, refine_root(fresh, k.a, k.b).evaluations);
    }
    // t − 0.3 on [0, 1]: the secant lands on the root at once.
    auto line = test::counted([](double t) { return ValueAndDerivative{t - 0.3, 1.0}; });
    const BracketResult r = refine_root(line, BracketPoint{0.0, {-0.3, std::numeric_limits<double>::quiet_NaN()}},
                                        BracketPoint{1.0, {0.7, std::numeric_limits<double>::quiet_NaN()}});
    EXPECT_LE(test::ulps_between(r.t, 0.3), 1);
    EXPECT_LE(line.calls, 3);
}

TEST(RefineRoot, ClosesTheBracketFromBothSides) {
    // Newton on the convex t² − 2 from t = 2 approaches √2 from above only;
    // the final bracket must still be two adjacent doubles around it.
    const BracketResult r = refine_root([](double t) { return ValueAndDerivative{t * t - 2.0, 2.0 * t}; }, 0.0, 2.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_EQ(std::nextafter(r.bracket.lo, 2.0), r.bracket.hi);
    EXPECT_LE(r.bracket.lo, std::numbers::sqrt2);
    EXPECT_GE(r.bracket.hi, std::numbers::sqrt2);
    // 0 and 2 (a tie in |H|, and H′(0) = 0: bisect to 1), then Newton 1.5,
    // 1.4167, 1.414216, 1.41421356237469, 1.4142135623730951 and one step
    // across the root to the double below.
    EXPECT_EQ(r.evaluations, 9);
}

TEST(RefineRoot, NearDoubleRootIsRefinedToFullPrecision) {
    // t² − 10⁻²⁰ on [0, 1]: Newton halves its way down from 1 (linear, like a
    // double root) until it reaches 10⁻¹⁰, then converges quadratically.
    auto h = test::counted([](double t) { return ValueAndDerivative{t * t - 1e-20, 2.0 * t}; });
    const BracketResult r = refine_root(h, 0.0, 1.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_LE(test::ulps_between(r.t, std::sqrt(1e-20)), 1);
    EXPECT_EQ(h.calls, r.evaluations);
    // Bisection takes 88 evaluations here (from width 1 to the spacing near 10⁻¹⁰).
    EXPECT_LE(r.evaluations, 50);
}

TEST(RefineRoot, MultipleRootsAreJumpedTo) {
    // On (t − 0.1)^m Newton gains only a factor (m − 1)/m per step; seeing
    // that ratio, refine_root steps m times as far and lands on the root.
    // (Without that, safeguarded Newton is linear here: slower than bisection.)
    for (const int power : {2, 3, 5, 9}) {
        SCOPED_TRACE(power);
        const double p = power;
        auto h = test::counted([p](double t) {
            const double d = t - 0.1;  // |d|^m with the sign of d: a sign change for every m
            return ValueAndDerivative{std::copysign(std::pow(std::abs(d), p), d), p * std::pow(std::abs(d), p - 1.0)};
        });
        const BracketResult r = refine_root(h, -1.0, 1.0);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, 0.1), 1);
        EXPECT_EQ(h.calls, r.evaluations);
        EXPECT_LE(r.evaluations, 10);
    }
}

TEST(RefineRoot, AMisleadingDerivativeFallsBackToBisection) {
    // H′ of the wrong sign sends every Newton point out of the bracket.
    auto h = test::counted([](double t) { return ValueAndDerivative{std::cos(t) - t, std::sin(t) + 1.0}; });
    const BracketResult r = refine_root(h, 0.0, 1.0);
    const BracketResult b = bisection([](double t) { return std::cos(t) - t; }, 0.0, 1.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_LE(test::ulps_between(r.t, 0.7390851332151606416553120876738734040134), 1);
    EXPECT_LE(r.evaluations, b.evaluations);
}

TEST(RefineRoot, ZeroAndInfiniteDerivativesBisect) {
    for (const double slope : {0.0, std::numeric_limits<double>::infinity()}) {
        const BracketResult r = refine_root([slope](double t) { return ValueAndDerivative{t - 0.3, slope}; }, 0.0, 1.0);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, 0.3), 1);
    }
}

TEST(RefineRoot, OnANonMonotoneBracketItFindsOneOfTheRoots) {
    // sin on [1, 10] changes sign at π, 2π and 3π.
    const BracketResult r = refine_root([](double t) { return ValueAndDerivative{std::sin(t), std::cos(t)}; }, 1.0, 10.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    const double k = std::round(r.t / std::numbers::pi);
    EXPECT_TRUE(k == 1.0 || k == 2.0 || k == 3.0) << r.t;
    EXPECT_LE(test::ulps_between(r.t, k * std::numbers::pi), 4);
    EXPECT_LE(r.evaluations, 20);
}

}  // namespace
}  // namespace zeroset
