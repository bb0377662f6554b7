// Sampling for sign changes: brackets in order, counted evaluations, the
// H ≤ 0 convention at exact zeros, NaN samples, early stop, and the roots it
// is documented to miss.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "root_test_support.hpp"
#include "zeroset/roots/refine.hpp"
#include "zeroset/roots/sign_change_brackets.hpp"

namespace zeroset {
namespace {

TEST(SignChangeBrackets, FindsEachSimpleRootInOrder) {
    auto h = test::counted([](double t) { return std::sin(t); });
    const SampledBrackets s = sign_change_brackets(h, 0.5, 10.0, 100);
    EXPECT_EQ(s.evaluations, 100);
    EXPECT_EQ(h.calls, 100);
    ASSERT_EQ(s.brackets.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const double root = static_cast<double>(i + 1) * std::numbers::pi;
        EXPECT_LT(s.brackets[i].lo, root);
        EXPECT_GT(s.brackets[i].hi, root);
        EXPECT_NEAR(s.brackets[i].hi - s.brackets[i].lo, 9.5 / 99.0, 1e-12);
    }
}

TEST(SignChangeBrackets, SamplesIncludeBothEndsExactly) {
    std::vector<double> ts;
    sign_change_brackets([&](double t) { ts.push_back(t); return 1.0; }, 0.1, 0.7, 7);
    ASSERT_EQ(ts.size(), 7u);
    EXPECT_EQ(ts.front(), 0.1);
    EXPECT_EQ(ts.back(), 0.7);
    for (std::size_t i = 1; i < ts.size(); ++i) EXPECT_NEAR(ts[i] - ts[i - 1], 0.1, 1e-15);
}

TEST(SignChangeBrackets, TwoRootsBetweenSamplesAreMissed) {
    // The documented limitation: (t − 1.4)(t − 1.6) is positive at 0, 1, 2, 3.
    const auto h = [](double t) { return (t - 1.4) * (t - 1.6); };
    EXPECT_TRUE(sign_change_brackets(h, 0.0, 3.0, 4).brackets.empty());
    EXPECT_EQ(sign_change_brackets(h, 0.0, 3.0, 31).brackets.size(), 2u);
}

TEST(SignChangeBrackets, ExactZeroSampleCountsAsInside) {
    // Entering at a sample: H = 1 − t is 1, 0, −1 at 0, 1, 2 — one bracket,
    // [0, 1], whose upper end is the root.
    const SampledBrackets entering = sign_change_brackets([](double t) { return 1.0 - t; }, 0.0, 2.0, 3);
    ASSERT_EQ(entering.brackets.size(), 1u);
    EXPECT_EQ(entering.brackets[0].lo, 0.0);
    EXPECT_EQ(entering.brackets[0].hi, 1.0);
    // Leaving at a sample: −1, 0, 1 — one bracket, [1, 2], whose lower end is the root.
    const SampledBrackets leaving = sign_change_brackets([](double t) { return t - 1.0; }, 0.0, 2.0, 3);
    ASSERT_EQ(leaving.brackets.size(), 1u);
    EXPECT_EQ(leaving.brackets[0].lo, 1.0);
    // Either way refinement returns the sample itself.
    const auto both = [](double t) { return ValueAndDerivative{1.0 - t, -1.0}; };
    EXPECT_EQ(refine_root(both, entering.brackets[0].lo, entering.brackets[0].hi).t, 1.0);
}

TEST(SignChangeBrackets, NaNSamplesEndNoBracket) {
    // sqrt(t) − 1 is NaN at −1 and −0.5 and −1 at 0: were NaN taken as
    // outside, [−0.5, 0] would be reported. Only the change at 1 (H = 0 there,
    // inside) to 1.5 is.
    const SampledBrackets s = sign_change_brackets([](double t) { return std::sqrt(t) - 1.0; }, -1.0, 3.0, 9);
    ASSERT_EQ(s.brackets.size(), 1u);
    EXPECT_EQ(s.brackets[0].lo, 1.0);
    EXPECT_EQ(s.brackets[0].hi, 1.5);
    EXPECT_EQ(s.evaluations, 9);
}

TEST(SignChangeBrackets, VisitorStopsTheSamplingAtTheFirstBracket) {
    auto h = test::counted([](double t) { return std::cos(t); });
    int visits = 0;
    const int evaluations = for_each_sign_change(h, 0.0, 10.0, 101, [&](const Bracket& b) {
        ++visits;
        EXPECT_LT(b.lo, std::numbers::pi / 2);
        EXPECT_GT(b.hi, std::numbers::pi / 2);
        return false;
    });
    EXPECT_EQ(visits, 1);
    EXPECT_EQ(evaluations, 17);  // samples 0, 0.1, …, 1.6: the change lies between 1.5 and 1.6
    EXPECT_EQ(h.calls, 17);
}

TEST(SignChangeBrackets, BadArgumentsThrow) {
    const auto h = [](double t) { return t; };
    EXPECT_THROW(sign_change_brackets(h, 0.0, 1.0, 1), std::invalid_argument);
    EXPECT_THROW(sign_change_brackets(h, 1.0, 0.0, 10), std::invalid_argument);
    EXPECT_THROW(sign_change_brackets(h, 0.0, std::numeric_limits<double>::infinity(), 10), std::invalid_argument);
    EXPECT_EQ(sign_change_brackets(h, 2.0, 2.0, 2).brackets.size(), 0u);
}

}  // namespace
}  // namespace zeroset
