// Regula falsi with the Anderson–Björck modification: superlinear on smooth
// functions where plain regula falsi crawls, never worse than a small
// multiple of bisection.
#include <gtest/gtest.h>

#include <cmath>

#include "root_test_support.hpp"
#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/regula_falsi.hpp"

namespace zeroset {
namespace {

TEST(RegulaFalsi, IsFarCheaperThanBisectionOnSmoothSimpleRoots) {
    for (const test::KnownRoot& k : test::known_roots()) {
        if (!k.simple) continue;
        SCOPED_TRACE(k.name);
        auto h = test::counted(k.h);
        const BracketResult r = regula_falsi(h, k.a, k.b);
        const BracketResult b = bisection(k.h, k.a, k.b);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_EQ(h.calls, r.evaluations);
        EXPECT_LE(r.evaluations, 18);
        EXPECT_LT(3 * r.evaluations, b.evaluations);
    }
}

TEST(RegulaFalsi, AndersonBjorckMovesTheEndPlainRegulaFalsiWouldKeep) {
    // t¹⁰ − 0.5 is convex on [0, 1.5]: plain regula falsi keeps the upper
    // end for ever and gains a few bits per step. Both ends must move here.
    auto h = test::counted([](double t) { return std::pow(t, 10.0) - 0.5; });
    const BracketResult r = regula_falsi(h, 0.0, 1.5);
    EXPECT_EQ(r.status, BracketStatus::Converged);
    EXPECT_LT(r.bracket.hi, 1.0);
    EXPECT_LE(test::ulps_between(r.t, 0.9330329915368074159813432661499421670272), 1);
    EXPECT_LE(r.evaluations, 20);
}

TEST(RegulaFalsi, MultipleRootsCostAtMostFourStepsPerHalving) {
    // Near a multiple root H is so flat that secant steps barely move: the
    // guard bisects. Bisection itself needs 56 to 58 evaluations on these.
    for (const test::KnownRoot& k : test::known_roots()) {
        if (k.simple) continue;
        SCOPED_TRACE(k.name);
        auto h = test::counted(k.h);
        const BracketResult r = regula_falsi(h, k.a, k.b);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(test::ulps_between(r.t, k.root), 1);
        EXPECT_EQ(h.calls, r.evaluations);
        EXPECT_LE(r.evaluations, 2 + 4 * 58);
    }
}

}  // namespace
}  // namespace zeroset
