// What bisection, regula falsi and refine_root share (bracket.hpp): every
// known root to full precision, roots at the ends of the bracket, brackets
// without a sign change, NaN, bad ends, the iteration cap, the x tolerance,
// the widest possible bracket, and evaluation counts that match the calls.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "root_test_support.hpp"
#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/refine.hpp"
#include "zeroset/roots/regula_falsi.hpp"

namespace zeroset {
namespace {

using test::KnownRoot;
using test::ulps_between;

using Fn = std::function<double(double)>;

/// A bracketing method run on H (and H′, which only refine_root uses),
/// counting the calls it makes.
struct Method {
    std::string name;
    std::function<BracketResult(const Fn& h, const Fn& dh, double a, double b, const BracketOptions&, int& calls)> run;
};

std::vector<Method> methods() {
    return {
        {"bisection",
         [](const Fn& h, const Fn&, double a, double b, const BracketOptions& o, int& calls) {
             return bisection([&](double t) {
                 ++calls;
                 return h(t);
             }, a, b, o);
         }},
        {"regula_falsi",
         [](const Fn& h, const Fn&, double a, double b, const BracketOptions& o, int& calls) {
             return regula_falsi([&](double t) {
                 ++calls;
                 return h(t);
             }, a, b, o);
         }},
        {"refine_root",
         [](const Fn& h, const Fn& dh, double a, double b, const BracketOptions& o, int& calls) {
             return refine_root([&](double t) {
                 ++calls;
                 return ValueAndDerivative{h(t), dh(t)};
             }, a, b, o);
         }},
    };
}

const Fn unit_slope = [](double) { return 1.0; };

TEST(Bracket, EveryMethodFindsEveryKnownRootToFullPrecision) {
    for (const Method& m : methods()) {
        for (const KnownRoot& k : test::known_roots()) {
            SCOPED_TRACE(m.name + " on " + k.name);
            int calls = 0;
            const BracketResult r = m.run(k.h, k.dh, k.a, k.b, {}, calls);
            ASSERT_EQ(r.status, BracketStatus::Converged);
            EXPECT_LE(ulps_between(r.t, k.root), 2) << r.t << " vs " << k.root;
            EXPECT_EQ(r.value, k.h(r.t));
            EXPECT_EQ(r.evaluations, calls);
            // Full precision: adjacent doubles, or an exact zero.
            if (r.value == 0.0) {
                EXPECT_EQ(r.bracket.lo, r.t);
                EXPECT_EQ(r.bracket.hi, r.t);
            } else {
                EXPECT_EQ(std::nextafter(r.bracket.lo, r.bracket.hi), r.bracket.hi);
                EXPECT_NE(is_inside(k.h(r.bracket.lo)), is_inside(k.h(r.bracket.hi)));
            }
        }
    }
}

TEST(Bracket, ExactZeroAtTheLowerEndIsReturnedAfterOneEvaluation) {
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r = m.run([](double t) { return t - 1.0; }, unit_slope, 1.0, 3.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_EQ(r.t, 1.0);
        EXPECT_EQ(r.value, 0.0);
        EXPECT_EQ(r.evaluations, 1);
        EXPECT_EQ(calls, 1);
    }
}

TEST(Bracket, ExactZeroAtTheUpperEndIsReturnedAfterTwoEvaluations) {
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r = m.run([](double t) { return 3.0 - t; }, unit_slope, 1.0, 3.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_EQ(r.t, 3.0);
        EXPECT_EQ(r.bracket.lo, 3.0);
        EXPECT_EQ(r.evaluations, 2);
        EXPECT_EQ(calls, 2);
    }
}

TEST(Bracket, ZerosAtBothEndsGiveTheLowerOne) {
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r =
            m.run([](double t) { return (t - 1.0) * (t - 2.0); }, unit_slope, 2.0, 1.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_EQ(r.t, 1.0);
        EXPECT_EQ(r.evaluations, 1);
    }
}

TEST(Bracket, EndsGivenInReverseOrderWork) {
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r =
            m.run([](double t) { return t * t - 2.0; }, [](double t) { return 2.0 * t; }, 2.0, 0.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(ulps_between(r.t, std::sqrt(2.0)), 1);
        EXPECT_LT(r.bracket.lo, r.bracket.hi);
    }
}

TEST(Bracket, SameSignAtBothEndsIsNoSignChange) {
    // A double root (t − 0.5)² touches zero but never changes sign: sampled
    // at the ends it cannot be bracketed, whatever lies between.
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r = m.run([](double t) { return (t - 0.5) * (t - 0.5); },
                                      [](double t) { return 2.0 * (t - 0.5); }, 0.0, 2.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::NoSignChange);
        EXPECT_EQ(r.evaluations, 2);
        EXPECT_EQ(calls, 2);
        EXPECT_EQ(r.bracket.lo, 0.0);
        EXPECT_EQ(r.bracket.hi, 2.0);
    }
}

TEST(Bracket, NonFiniteEndsAreInvalidAndNothingIsEvaluated) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        for (const auto& [a, b] : std::vector<std::pair<double, double>>{{0.0, inf}, {-inf, 1.0}, {nan, 1.0}}) {
            int calls = 0;
            const BracketResult r = m.run([](double t) { return t - 0.5; }, unit_slope, a, b, {}, calls);
            EXPECT_EQ(r.status, BracketStatus::InvalidBracket);
            EXPECT_EQ(r.evaluations, 0);
            EXPECT_EQ(calls, 0);
            EXPECT_TRUE(std::isnan(r.t));
        }
    }
}

TEST(Bracket, NaNStopsTheSearchAndKeepsTheLastGoodBracket) {
    // H is NaN on (0.2, 0.85), where every method probes first (refine_root
    // is given a wrong slope of 1, so its Newton point from t = 1 is 0.8).
    const Fn h = [](double t) { return t > 0.2 && t < 0.85 ? std::sqrt(-1.0 - t) : (t - 0.9) * (t + 1.0); };
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r = m.run(h, unit_slope, 0.0, 1.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::NotANumber);
        EXPECT_EQ(r.evaluations, calls);
        EXPECT_EQ(r.evaluations, 3);
        EXPECT_EQ(r.bracket.lo, 0.0);
        EXPECT_EQ(r.bracket.hi, 1.0);
        EXPECT_FALSE(std::isnan(r.value));
    }
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name + " with NaN at the lower end");
        int calls = 0;
        const BracketResult r = m.run([](double t) { return std::log(t); }, unit_slope, -1.0, 2.0, {}, calls);
        EXPECT_EQ(r.status, BracketStatus::NotANumber);
        EXPECT_EQ(r.evaluations, 1);
    }
}

TEST(Bracket, IterationCapStopsWithAValidBracket) {
    BracketOptions options;
    options.max_iterations = 3;
    const KnownRoot k = test::known_roots()[1];  // cos t − t: every method needs more than 3 steps
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int calls = 0;
        const BracketResult r = m.run(k.h, k.dh, k.a, k.b, options, calls);
        EXPECT_EQ(r.status, BracketStatus::MaxIterations);
        EXPECT_EQ(r.evaluations, 2 + 3);
        EXPECT_EQ(calls, 5);
        EXPECT_LT(r.bracket.lo, k.root);
        EXPECT_GT(r.bracket.hi, k.root);
        EXPECT_TRUE(r.t == r.bracket.lo || r.t == r.bracket.hi);
    }
}

TEST(Bracket, CoarseToleranceStopsEarlyAroundTheRoot) {
    BracketOptions coarse;
    coarse.x_tolerance = 1e-6;
    const KnownRoot k = test::known_roots()[1];  // cos t − t
    for (const Method& m : methods()) {
        SCOPED_TRACE(m.name);
        int coarse_calls = 0;
        int fine_calls = 0;
        const BracketResult r = m.run(k.h, k.dh, k.a, k.b, coarse, coarse_calls);
        const BracketResult full = m.run(k.h, k.dh, k.a, k.b, {}, fine_calls);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        EXPECT_LE(r.bracket.hi - r.bracket.lo, 1e-6);
        EXPECT_LE(r.bracket.lo, k.root);
        EXPECT_GE(r.bracket.hi, k.root);
        EXPECT_LE(r.evaluations, full.evaluations);
        // Bisection halves [0, 1] twenty times to get below 10⁻⁶.
        if (m.name == "bisection") {
            EXPECT_EQ(r.evaluations, 2 + 20);
        }
    }
}

TEST(Bracket, WidestBracketConvergesToATinyRootWithinTheBound) {
    const double max = std::numeric_limits<double>::max();
    for (const double root : {1e-300, 5e-320, -3.0e300}) {
        for (const Method& m : methods()) {
            SCOPED_TRACE(m.name + " root " + std::to_string(root));
            int calls = 0;
            const BracketResult r = m.run([root](double t) { return t - root; }, unit_slope, -max, max, {}, calls);
            EXPECT_EQ(r.status, BracketStatus::Converged);
            EXPECT_LE(ulps_between(r.t, root), 1);
            EXPECT_LE(r.evaluations, 2 + (m.name == "bisection" ? max_bisections : 4 * max_bisections + 8));
        }
    }
}

}  // namespace
}  // namespace zeroset
