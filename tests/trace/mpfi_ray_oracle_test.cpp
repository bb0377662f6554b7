// The first-hit oracle itself, on functions whose roots are known in closed
// form: every op of the op table, roots at the span's ends, tangent and
// triple roots, kinks, poles, jumps, undefined stretches and near misses.
// The ray suite's references are only as good as this.
#include "support/mpfi_ray_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace zeroset::test {
namespace {

const Expr x = var_x();
const Ray along_x{{0, 0, 0}, {1, 0, 0}};

/// The unit sphere at the origin.
Expr unit_sphere() { return square(var_x()) + square(var_y()) + square(var_z()) - 1.0; }

struct KnownRoot {
    std::string what;
    Expr f;
    Span span;
    double root;
};

TEST(MpfiRayOracle, FindsTheFirstRootThroughEveryOp) {
    const KnownRoot cases[] = {
        {"sqrt", sqrt(x) - 2.0, {0.5, 10.0}, 4.0},
        {"log", log(x) - 1.0, {0.5, 5.0}, std::numbers::e},
        {"exp", exp(x) - 3.0, {0.0, 2.0}, std::log(3.0)},
        {"sin", sin(x), {2.0, 4.0}, std::numbers::pi},
        {"cos", cos(x), {0.0, 3.0}, std::numbers::pi / 2},
        {"powi", powi(x, 3) - 2.0, {0.0, 3.0}, std::cbrt(2.0)},
        {"negative powi", powi(x, -2) - 4.0, {0.1, 3.0}, 0.5},
        {"pow, constant exponent", pow(x, Expr(2.5)) - 2.0, {0.0, 3.0}, std::pow(2.0, 0.4)},
        {"pow, variable exponent", pow(Expr(2.0), x) - 3.0, {0.0, 3.0}, std::log2(3.0)},
        {"div", x / (x + 1.0) - 0.5, {0.0, 3.0}, 1.0},
        {"neg", -x + 2.5, {0.0, 3.0}, 2.5},
        {"mul", (x - 0.5) * (x - 2.0), {-1.0, 1.0}, 0.5},
        {"abs", abs(x - 1.5) - 0.25, {0.0, 3.0}, 1.25},
        {"min", min(x + 1.0, 3.0 - x), {0.0, 5.0}, 3.0},
        {"max", max(1.0 - x, x - 5.0), {0.0, 6.0}, 1.0},
        {"tan", tan(x) - 1.0, {0.0, 1.5}, std::numbers::pi / 4},
        {"atan", atan(x) - 1.0, {0.0, 3.0}, std::tan(1.0)},
        {"atan2", atan2(Expr(1.0), x) - std::numbers::pi / 3, {-2.0, 2.0}, 1.0 / std::sqrt(3.0)},
        {"floor", floor(x) + x - 2.25, {0.0, 3.0}, 1.25},
        {"hypot", hypot(x, Expr(0.6)) - 1.0, {0.0, 3.0}, 0.8},
    };
    for (const KnownRoot& c : cases) {
        MpfiRayOracle oracle(c.f, 1.0);
        const auto root = oracle.first_root(along_x, c.span);
        ASSERT_TRUE(root.has_value()) << c.what;
        EXPECT_EQ(root->kind, RootKind::Simple) << c.what;
        EXPECT_NEAR(root->t, c.root, 4.5e-16 * c.root) << c.what;
        EXPECT_GT(root->slope, 0.0) << c.what;
    }
}

TEST(MpfiRayOracle, SphereRootIsExactAndItsSlopeIsTheDerivative) {
    MpfiRayOracle oracle(unit_sphere(), 1.0);
    const Ray ray{{-3, 0.5, 0}, {1, 0, 0}};
    const auto root = oracle.first_root(ray, {0.0, 10.0});
    ASSERT_TRUE(root.has_value());
    EXPECT_EQ(root->kind, RootKind::Simple);
    const long double half_chord = std::sqrt(0.75L);
    EXPECT_NEAR(root->t, static_cast<double>(3.0L - half_chord), 2.5e-16);    // the nearest double: half an ulp
    EXPECT_NEAR(root->slope, static_cast<double>(2.0L * half_chord), 1e-12);  // |H′| = |2(t − 3)|
}

TEST(MpfiRayOracle, RootsAtTheEndsOfTheSpanCount) {
    MpfiRayOracle oracle(unit_sphere(), 1.0);
    const Ray ray{{-3, 0, 0}, {1, 0, 0}};  // roots at t = 2 and 4, exactly
    EXPECT_EQ(oracle.first_root(ray, {2.0, 5.0})->t, 2.0);
    EXPECT_EQ(oracle.first_root(ray, {0.0, 2.0})->t, 2.0);
    EXPECT_EQ(oracle.first_root(ray, {2.5, 5.0})->t, 4.0);
    EXPECT_FALSE(oracle.first_root(ray, {0.0, 2.0 - 1e-12}).has_value());
    EXPECT_EQ(oracle.first_root(ray, {2.0 - 1e-12, 5.0})->t, 2.0);
}

TEST(MpfiRayOracle, ExactTangentIsTangent) {
    MpfiRayOracle oracle(unit_sphere(), 1.0);
    const auto root = oracle.first_root({{-3, 1, 0}, {1, 0, 0}}, {0.0, 10.0});
    ASSERT_TRUE(root.has_value());
    EXPECT_EQ(root->kind, RootKind::Tangent);
    EXPECT_NEAR(root->t, 3.0, 1e-12);
}

TEST(MpfiRayOracle, NarrowMissesAndShallowDipsAreResolved) {
    MpfiRayOracle oracle(unit_sphere(), 1.0);
    for (const double gap : {1e-6, 1e-9, 1e-12}) {
        EXPECT_FALSE(oracle.first_root({{-3, 1 + gap, 0}, {1, 0, 0}}, {0.0, 10.0}).has_value()) << gap;
        const double y = 1 - gap;
        const auto roots = oracle.all_roots({{-3, y, 0}, {1, 0, 0}}, {0.0, 10.0}, 4);
        const double half_chord = std::sqrt((1 - y) * (1 + y));
        ASSERT_EQ(roots.size(), 2U) << gap;
        EXPECT_EQ(roots[0].kind, RootKind::Simple);
        EXPECT_NEAR(roots[0].t, 3.0 - half_chord, 1e-15) << gap;
        EXPECT_NEAR(roots[1].t, 3.0 + half_chord, 1e-15) << gap;
    }
}

TEST(MpfiRayOracle, TripleRootIsAProvenCrossing) {
    MpfiRayOracle oracle(powi(1.5 - x, 3), 1.0);
    const auto root = oracle.first_root(along_x, {0.0, 3.0});
    ASSERT_TRUE(root.has_value());
    EXPECT_EQ(root->kind, RootKind::Multiple);
    EXPECT_NEAR(root->t, 1.5, 1e-12);
}

TEST(MpfiRayOracle, KinkTouchingZeroIsTangent) {
    MpfiRayOracle oracle(abs(x - 2.0), 1.0);
    const auto root = oracle.first_root(along_x, {0.0, 3.0});
    ASSERT_TRUE(root.has_value());
    EXPECT_EQ(root->kind, RootKind::Tangent);
    EXPECT_NEAR(root->t, 2.0, 1e-12);
}

TEST(MpfiRayOracle, AllRootsInOrderUpToTheCap) {
    MpfiRayOracle oracle(sin(x), 1.0);
    const auto roots = oracle.all_roots(along_x, {0.5, 10.0}, 10);
    ASSERT_EQ(roots.size(), 3U);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(roots[k].kind, RootKind::Simple);
        EXPECT_NEAR(roots[k].t, (k + 1) * std::numbers::pi, 1e-15 * (k + 1) * std::numbers::pi);
    }
    EXPECT_EQ(oracle.all_roots(along_x, {0.5, 10.0}, 2).size(), 2U);
}

TEST(MpfiRayOracle, ASignChangeAcrossAPoleIsNoRoot) {
    MpfiRayOracle oracle(1.0 / (x - 2.0), 1.0);
    for (const OracleRoot& root : oracle.all_roots(along_x, {0.0, 4.0}, 10))
        EXPECT_EQ(root.kind, RootKind::Tangent) << root.t;  // 0 cannot be excluded at the pole, but nothing is proven
}

// A jump across 0 is no proven root either: floor, tan and atan2 over their
// integers, poles and cut are irregular, so 0 there is at best a tangent.
TEST(MpfiRayOracle, JumpsAreNoProvenRoots) {
    const Expr y = var_y();
    const struct {
        std::string what;
        Expr f;
        Span span;
    } jumps[] = {
        {"floor", floor(x) - 1.5, {0.0, 3.0}},                  // −1.5, −0.5, then 0.5 from x = 2
        {"tan", -tan(x), {1.0, 2.0}},                           // −1.6 … −∞, then +∞ … 2.2
        {"atan2", atan2(y - 1e-3 * x, Expr(-1.0)), {-1.0, 1.0}}, // π … −π across the cut at x = 0
    };
    for (const auto& j : jumps) {
        MpfiRayOracle oracle(j.f, 1.0);
        const Ray ray{{0, 0, 0}, {1, 0, 0}};
        for (const OracleRoot& root : oracle.all_roots(ray, j.span, 10))
            EXPECT_EQ(root.kind, RootKind::Tangent) << j.what << " at " << root.t;
    }
}

TEST(MpfiRayOracle, UndefinedStretchesHoldNoRoot) {
    const auto log_root = MpfiRayOracle(log(x), 1.0).first_root(along_x, {-1.0, 3.0});
    ASSERT_TRUE(log_root.has_value());
    EXPECT_EQ(log_root->kind, RootKind::Simple);
    EXPECT_EQ(log_root->t, 1.0);
    EXPECT_FALSE(MpfiRayOracle(sqrt(x - 1.0) + 0.5, 1.0).first_root(along_x, {-1.0, 3.0}).has_value());
}

TEST(MpfiRayOracle, SignAtAPoint) {
    MpfiRayOracle oracle(unit_sphere(), 1.0);
    const Ray ray{{-3, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(oracle.sign(ray, 0.0), 1);
    EXPECT_EQ(oracle.sign(ray, 3.0), -1);
    EXPECT_EQ(oracle.sign(ray, 2.0), 0);
}

}  // namespace
}  // namespace zeroset::test
