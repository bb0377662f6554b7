// Newton's method (eq. 22): quadratic on simple roots, linear on a double
// root, and every way it fails reported as such, in a bounded number of steps.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "root_test_support.hpp"
#include "zeroset/roots/newton.hpp"

namespace zeroset {
namespace {

ValueAndDerivative sqrt2_h(double t) { return {t * t - 2.0, 2.0 * t}; }
ValueAndDerivative atan_h(double t) { return {std::atan(t), 1.0 / (1.0 + t * t)}; }
ValueAndDerivative cbrt_h(double t) { return {std::cbrt(t), 1.0 / (3.0 * std::cbrt(t) * std::cbrt(t))}; }

TEST(Newton, ConvergesQuadraticallyOnSimpleRoots) {
    for (const test::KnownRoot& k : test::known_roots()) {
        if (!k.simple) continue;
        SCOPED_TRACE(k.name);
        auto h = test::counted([&k](double t) { return k.both(t); });
        // Start a tenth of the bracket away from the root, on its upper side.
        const NewtonResult r = newton(h, k.root + 0.1 * (k.b - k.a) * (k.name == "steep_tanh" ? 0.1 : 1.0));
        EXPECT_EQ(r.status, NewtonStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, k.root), 2) << r.t;
        EXPECT_EQ(h.calls, r.evaluations);
        EXPECT_LE(r.evaluations, 10);
    }
}

TEST(Newton, RecordsEveryIterateForPlots) {
    std::vector<double> iterates;
    NewtonOptions options;
    options.iterates = &iterates;
    const NewtonResult r = newton(sqrt2_h, 1.0, options);
    ASSERT_EQ(r.status, NewtonStatus::Converged);
    ASSERT_EQ(iterates.size(), static_cast<std::size_t>(r.evaluations) + 1);
    EXPECT_EQ(iterates[0], 1.0);
    EXPECT_EQ(iterates[1], 1.5);
    EXPECT_DOUBLE_EQ(iterates[2], 17.0 / 12.0);
    EXPECT_DOUBLE_EQ(iterates[3], 577.0 / 408.0);
    EXPECT_EQ(iterates.back(), r.t);
}

TEST(Newton, DoubleRootConvergesOnlyLinearly) {
    // On t² every step halves t: about 50 steps to reach the tolerance, where
    // a simple root takes 6.
    auto h = test::counted([](double t) { return ValueAndDerivative{t * t, 2.0 * t}; });
    const NewtonResult r = newton(h, 1.0);
    EXPECT_EQ(r.status, NewtonStatus::Converged);
    EXPECT_LE(std::abs(r.t), 1e-15);
    EXPECT_GE(r.evaluations, 45);
    EXPECT_LE(r.evaluations, 55);
    EXPECT_EQ(h.calls, r.evaluations);
}

TEST(Newton, ExactZeroAtTheStartConvergesAtOnce) {
    const NewtonResult z = newton([](double t) { return ValueAndDerivative{t - 0.5, 1.0}; }, 0.5);
    EXPECT_EQ(z.status, NewtonStatus::Converged);
    EXPECT_EQ(z.t, 0.5);
    EXPECT_EQ(z.evaluations, 1);
}

TEST(Newton, ZeroDerivativeStalls) {
    // cos has a root at π/2, but from its peak at 0 eq. 22 has no next point.
    const NewtonResult r = newton([](double t) { return ValueAndDerivative{std::cos(t), -std::sin(t)}; }, 0.0);
    EXPECT_EQ(r.status, NewtonStatus::Stalled);
    EXPECT_EQ(r.t, 0.0);
    EXPECT_EQ(r.evaluations, 1);
}

TEST(Newton, AtanFromOnePointFiveLeavesTheDomain) {
    // The classic runaway: |t| grows every step, 1.5 → −1.69 → 2.32 → −5.11 → 32.3 → −1575.
    std::vector<double> iterates;
    NewtonOptions options;
    options.domain = Interval(-100.0, 100.0);
    options.iterates = &iterates;
    const NewtonResult r = newton(atan_h, 1.5, options);
    EXPECT_EQ(r.status, NewtonStatus::Diverged);
    EXPECT_EQ(r.evaluations, 5);
    EXPECT_NEAR(r.t, -1575.0, 1.0);
    EXPECT_EQ(iterates.back(), r.t);
    for (std::size_t i = 2; i < iterates.size(); ++i) EXPECT_GT(std::abs(iterates[i]), std::abs(iterates[i - 1]));
}

TEST(Newton, AtanOnTheWholeLineStallsWhereTheSlopeUnderflows) {
    // Without a domain the runaway goes on until 1 + t² overflows and H′ = 0.
    const NewtonResult r = newton(atan_h, 1.5);
    EXPECT_EQ(r.status, NewtonStatus::Stalled);
    EXPECT_GT(std::abs(r.t), 1e154);
    EXPECT_EQ(r.evaluations, 12);
}

TEST(Newton, CubeRootDivergesByDoubling) {
    // For t^(1/3) eq. 22 gives t − 3t = −2t (up to rounding): each step doubles |t|.
    NewtonOptions bounded;
    bounded.domain = Interval(-1000.0, 1000.0);
    const NewtonResult r = newton(cbrt_h, 1.0, bounded);
    EXPECT_EQ(r.status, NewtonStatus::Diverged);
    EXPECT_NEAR(r.t, 1024.0, 1e-9);
    EXPECT_EQ(r.evaluations, 10);
    // Unbounded, it never leaves the finite doubles in 64 steps: the cap ends it.
    const NewtonResult u = newton(cbrt_h, 1.0);
    EXPECT_EQ(u.status, NewtonStatus::MaxIterations);
    EXPECT_EQ(u.evaluations, 64);
    EXPECT_NEAR(std::abs(u.t) / std::ldexp(1.0, 64), 1.0, 1e-12);
}

TEST(Newton, NonFiniteValuesDiverge) {
    const NewtonResult nan_value = newton([](double t) { return ValueAndDerivative{std::sqrt(t) - 2.0, 0.5 / std::sqrt(t)}; }, -1.0);
    EXPECT_EQ(nan_value.status, NewtonStatus::Diverged);
    EXPECT_EQ(nan_value.evaluations, 1);
    const NewtonResult infinite_slope = newton(
        [](double t) { return ValueAndDerivative{t - 1.0, std::numeric_limits<double>::infinity()}; }, 0.0);
    EXPECT_EQ(infinite_slope.status, NewtonStatus::Diverged);
    // An overflowing step: H′ is subnormal.
    const NewtonResult huge_step = newton([](double t) { return ValueAndDerivative{t + 1e300, 1e-300}; }, 0.0);
    EXPECT_EQ(huge_step.status, NewtonStatus::Diverged);
    EXPECT_EQ(huge_step.evaluations, 1);
}

TEST(Newton, StartOutsideTheDomainEvaluatesNothing) {
    NewtonOptions options;
    options.domain = Interval(0.0, 1.0);
    auto h = test::counted(sqrt2_h);
    const NewtonResult r = newton(h, 2.0, options);
    EXPECT_EQ(r.status, NewtonStatus::Diverged);
    EXPECT_EQ(r.evaluations, 0);
    EXPECT_EQ(h.calls, 0);
    EXPECT_EQ(newton(h, std::numeric_limits<double>::quiet_NaN()).status, NewtonStatus::Diverged);
}

TEST(Newton, IterationCapAndToleranceAreHonoured) {
    NewtonOptions capped;
    capped.max_iterations = 3;
    auto h = test::counted(sqrt2_h);
    const NewtonResult r = newton(h, 100.0, capped);
    EXPECT_EQ(r.status, NewtonStatus::MaxIterations);
    EXPECT_EQ(r.evaluations, 3);
    EXPECT_EQ(h.calls, 3);

    NewtonOptions loose;
    loose.tolerance = 1e-3;
    const NewtonResult coarse = newton(sqrt2_h, 100.0, loose);
    const NewtonResult fine = newton(sqrt2_h, 100.0);
    EXPECT_EQ(coarse.status, NewtonStatus::Converged);
    EXPECT_LT(coarse.evaluations, fine.evaluations);
    EXPECT_NEAR(coarse.t, std::numbers::sqrt2, 1e-5);  // quadratic: error ≪ the last step
}

}  // namespace
}  // namespace zeroset
