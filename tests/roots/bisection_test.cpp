// Bisection (the survey's Fig. 6): one bit per evaluation, to adjacent
// doubles, and an exact zero at a midpoint ends it (step 2 of the figure).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "root_test_support.hpp"
#include "zeroset/roots/bisection.hpp"

namespace zeroset {
namespace {

TEST(Bisection, GainsOneBitPerEvaluation) {
    // [1, 2] holds doubles 2^−52 apart: 52 halvings reach adjacent doubles.
    auto h = test::counted([](double t) { return t * t - 2.0; });
    const BracketResult r = bisection(h, 1.0, 2.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_LE(test::ulps_between(r.t, std::numbers::sqrt2), 1);
    EXPECT_EQ(r.evaluations, 2 + 52);
    EXPECT_EQ(h.calls, r.evaluations);
}

TEST(Bisection, ExactZeroAtAMidpointEndsTheSearch) {
    // Fig. 6, step 2: the first midpoint of [0, 2] is the root 1.
    auto h = test::counted([](double t) { return t * t * t - 1.0; });
    const BracketResult r = bisection(h, 0.0, 2.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_EQ(r.t, 1.0);
    EXPECT_EQ(r.value, 0.0);
    EXPECT_EQ(r.evaluations, 3);
    EXPECT_EQ(h.calls, 3);
}

TEST(Bisection, KeepsTheHalfWhoseEndsDiffer) {
    // Three roots in [0, 10]; bisection picks the one its halving leads to
    // (midpoint 5 lies between the roots 4.5 and 6.5), not the first.
    const auto h = [](double t) { return (t - 1.5) * (t - 4.5) * (t - 6.5); };
    const BracketResult r = bisection(h, 0.0, 10.0);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_EQ(r.t, 6.5);
}

TEST(Bisection, CountsEveryEvaluationOnTheWidestBracket) {
    const double max = std::numeric_limits<double>::max();
    auto h = test::counted([](double t) { return t - 0.75; });
    const BracketResult r = bisection(h, -max, max);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_EQ(r.t, 0.75);
    EXPECT_EQ(h.calls, r.evaluations);
    // The width must fall from 2^1025 to below 1 (1024 halvings), then to the
    // spacing near 0.75 (53 more); 0.75 itself gets evaluated on the way.
    EXPECT_GE(r.evaluations, 2 + 1024);
    EXPECT_LE(r.evaluations, 2 + 1024 + 54);
}

}  // namespace
}  // namespace zeroset
