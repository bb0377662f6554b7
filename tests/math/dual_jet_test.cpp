// Dual and Jet: every derivative rule against its closed form, for plain
// numbers and for intervals (the enclosure must contain the point derivative),
// and unbounded derivatives where floor, tan and atan2 jump.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "zeroset/math/dual.hpp"
#include "zeroset/math/jet.hpp"

namespace zeroset {
namespace {

/// A unary rule: the function applied generically, and its closed-form g, g′, g″.
struct Rule {
    std::string name;
    std::function<Dual<double>(const Dual<double>&)> dual;
    std::function<Jet<double>(const Jet<double>&)> jet;
    std::function<Dual<Interval>(const Dual<Interval>&)> dual_interval;
    std::function<Jet<Interval>(const Jet<Interval>&)> jet_interval;
    std::function<double(double)> g, g1, g2;
    std::vector<double> at;  // sample arguments
};

template <class F>
Rule make_rule(std::string name, F f, double (*g)(double), double (*g1)(double), double (*g2)(double),
               std::vector<double> at) {
    return {std::move(name), f, f, f, f, g, g1, g2, std::move(at)};
}

// `body` is written once over the number type N of the argument u.
#define ZEROSET_RULE(name, body, g, g1, g2, ...)                                                                       \
    make_rule(                                                                                                         \
        name,                                                                                                          \
        [](const auto& u) {                                                                                            \
            using N = std::remove_cvref_t<decltype(u)>;                                                                \
            return N(body);                                                                                            \
        },                                                                                                             \
        []([[maybe_unused]] double v) -> double { return g; }, []([[maybe_unused]] double v) -> double { return g1; }, \
        []([[maybe_unused]] double v) -> double { return g2; }, {__VA_ARGS__})

std::vector<Rule> rules() {
    using std::cos, std::exp, std::log, std::pow, std::sin, std::sqrt;
    return {
        ZEROSET_RULE("square", square(u), v * v, 2 * v, 2.0, -1.5, 0.0, 0.7),
        ZEROSET_RULE("sqrt", sqrt(u), sqrt(v), 0.5 / sqrt(v), -0.25 / (v * sqrt(v)), 0.3, 2.0, 9.0),
        ZEROSET_RULE("exp", exp(u), exp(v), exp(v), exp(v), -2.0, 0.0, 1.5),
        ZEROSET_RULE("log", log(u), log(v), 1 / v, -1 / (v * v), 0.2, 1.0, 7.0),
        ZEROSET_RULE("sin", sin(u), sin(v), cos(v), -sin(v), -2.0, 0.0, 1.5707963267948966, 4.0),
        ZEROSET_RULE("cos", cos(u), cos(v), -sin(v), -cos(v), -2.0, 0.0, 3.0, 4.0),
        ZEROSET_RULE("abs", abs(u), std::abs(v), v < 0 ? -1.0 : 1.0, 0.0, -2.0, 0.5),
        ZEROSET_RULE("neg", -u, -v, -1.0, 0.0, -2.0, 0.5),
        ZEROSET_RULE("powi 1", powi(u, 1), v, 1.0, 0.0, -1.5, 0.0, 2.0),
        ZEROSET_RULE("powi 3", powi(u, 3), v * v * v, 3 * v * v, 6 * v, -1.5, 0.0, 2.0),
        ZEROSET_RULE("powi 4", powi(u, 4), v * v * v * v, 4 * v * v * v, 12 * v * v, -1.5, 0.0, 2.0),
        ZEROSET_RULE("powi -2", powi(u, -2), 1 / (v * v), -2 / (v * v * v), 6 / (v * v * v * v), -1.5, 0.5, 2.0),
        ZEROSET_RULE("pow 2.5", pow(u, N(2.5)), pow(v, 2.5), 2.5 * pow(v, 1.5), 3.75 * pow(v, 0.5), 0.5, 2.0),
        ZEROSET_RULE("pow -0.5", pow(u, N(-0.5)), pow(v, -0.5), -0.5 * pow(v, -1.5), 0.75 * pow(v, -2.5), 0.5, 2.0),
        // An integral exponent reached through pow (a .vm `pow`, or |n| > 1024):
        // negative bases are in its domain.
        ZEROSET_RULE("pow 3", pow(u, N(3.0)), v * v * v, 3 * v * v, 6 * v, -1.5, 0.0, 2.0),
        ZEROSET_RULE("pow 1", pow(u, N(1.0)), v, 1.0, 0.0, -1.5, 0.0, 2.0),
        ZEROSET_RULE("pow -3", pow(u, N(-3.0)), 1 / (v * v * v), -3 / (v * v * v * v), 12 / (v * v * v * v * v), -1.5,
                     0.5),
        ZEROSET_RULE("tan", tan(u), std::tan(v), 1 + std::tan(v) * std::tan(v),
                     2 * std::tan(v) * (1 + std::tan(v) * std::tan(v)), -1.0, 0.0, 1.2),
        ZEROSET_RULE("atan", atan(u), std::atan(v), 1 / (1 + v * v), -2 * v / ((1 + v * v) * (1 + v * v)), -3.0, 0.0,
                     0.8),
        ZEROSET_RULE("atan2(u, 0.5)", atan2(u, N(0.5)), std::atan2(v, 0.5), 0.5 / (0.25 + v * v),
                     -v / ((0.25 + v * v) * (0.25 + v * v)), -1.5, 0.0, 2.0),
        ZEROSET_RULE("atan2(0.5, u)", atan2(N(0.5), u), std::atan2(0.5, v), -0.5 / (0.25 + v * v),
                     v / ((0.25 + v * v) * (0.25 + v * v)), -1.5, 0.0, 2.0),
        ZEROSET_RULE("hypot(u, 0.7)", hypot(u, N(0.7)), std::hypot(v, 0.7), v / std::hypot(v, 0.7),
                     0.49 / std::pow(std::hypot(v, 0.7), 3), -1.5, 0.0, 2.0),
        // ln(eᵘ + e^0.4): slope σ(u − 0.4), curvature σ(1 − σ).
        ZEROSET_RULE("log_sum_exp(u, 0.4)", log_sum_exp(u, N(0.4)), std::log(exp(v) + exp(0.4)),
                     1 / (1 + exp(0.4 - v)), exp(0.4 - v) / ((1 + exp(0.4 - v)) * (1 + exp(0.4 - v))), -30.0, -1.5,
                     0.4, 2.0, 30.0),
        ZEROSET_RULE("floor", floor(u), std::floor(v), 0.0, 0.0, -1.5, 0.3, 2.7),
        ZEROSET_RULE("u*u", u * u, v * v, 2 * v, 2.0, -1.5, 0.0, 0.7),
        ZEROSET_RULE("1/u", N(1.0) / u, 1 / v, -1 / (v * v), 2 / (v * v * v), -1.5, 0.5),
        ZEROSET_RULE("min(u, 1-u)", min(u, N(1.0) - u), std::min(v, 1 - v), v < 0.5 ? 1.0 : -1.0, 0.0, -1.0, 0.2, 0.8),
        ZEROSET_RULE("max(u, 1-u)", max(u, N(1.0) - u), std::max(v, 1 - v), v > 0.5 ? 1.0 : -1.0, 0.0, -1.0, 0.2, 0.8),
    };
}

double tolerance(double expected) { return 1e-13 * (1.0 + std::abs(expected)); }

TEST(Dual, ChainRuleAgainstClosedForms) {
    for (const Rule& rule : rules()) {
        for (const double v : rule.at) {
            // Along a direction with all three components, so the gradient scales by them.
            const Dual<double> u{v, {0.5, -2.0, 1.0}};
            const Dual<double> r = rule.dual(u);
            EXPECT_NEAR(r.v, rule.g(v), tolerance(rule.g(v))) << rule.name << " at " << v;
            EXPECT_NEAR(r.g.x, 0.5 * rule.g1(v), tolerance(rule.g1(v))) << rule.name << " at " << v;
            EXPECT_NEAR(r.g.y, -2.0 * rule.g1(v), tolerance(rule.g1(v))) << rule.name << " at " << v;
            EXPECT_NEAR(r.g.z, rule.g1(v), tolerance(rule.g1(v))) << rule.name << " at " << v;
        }
    }
}

TEST(Jet, ChainRuleAgainstClosedForms) {
    for (const Rule& rule : rules()) {
        for (const double v : rule.at) {
            // u(t) = v + 0.5 (t − t₀) + 0.25 (t − t₀)² around t₀: u′ = 0.5, u″ = 0.5.
            const Jet<double> u{v, 0.5, 0.5};
            const Jet<double> r = rule.jet(u);
            const double d1 = rule.g1(v) * 0.5, d2 = rule.g2(v) * 0.25 + rule.g1(v) * 0.5;
            EXPECT_NEAR(r.v, rule.g(v), tolerance(rule.g(v))) << rule.name << " at " << v;
            EXPECT_NEAR(r.d1, d1, tolerance(d1)) << rule.name << " at " << v;
            EXPECT_NEAR(r.d2, d2, tolerance(d2)) << rule.name << " at " << v;
        }
    }
}

/// An interval around v of half-width w, as a number type with derivatives.
TEST(DualInterval, EnclosesThePointDerivatives) {
    for (const Rule& rule : rules()) {
        for (const double v : rule.at) {
            for (const double w : {0.0, 1e-9, 1e-3, 0.1}) {
                const Interval a{v - w, v + w};
                const Dual<Interval> r = rule.dual_interval({a, {Interval(0.5), Interval(-2.0), Interval(1.0)}});
                for (const double s : {v - w, v, v + w}) {
                    const double g = rule.g(s), g1 = rule.g1(s);
                    if (!std::isfinite(g) || !std::isfinite(g1)) continue;
                    const std::string where = rule.name + " over [" + std::to_string(a.lo) + ", " +
                                              std::to_string(a.hi) + "] at " + std::to_string(s);
                    EXPECT_TRUE(r.v.contains(g)) << where << ": value [" << r.v.lo << ", " << r.v.hi << "] ∌ " << g;
                    EXPECT_TRUE(r.g.x.contains(0.5 * g1)) << where << ": [" << r.g.x.lo << ", " << r.g.x.hi << "]";
                    EXPECT_TRUE(r.g.y.contains(-2.0 * g1)) << where << ": [" << r.g.y.lo << ", " << r.g.y.hi << "]";
                    EXPECT_TRUE(r.g.z.contains(g1)) << where << ": [" << r.g.z.lo << ", " << r.g.z.hi << "]";
                }
            }
        }
    }
}

TEST(JetInterval, EnclosesThePointDerivatives) {
    for (const Rule& rule : rules()) {
        for (const double v : rule.at) {
            for (const double w : {0.0, 1e-9, 1e-3, 0.1}) {
                const Interval a{v - w, v + w};
                const Jet<Interval> r = rule.jet_interval({a, Interval(0.5), Interval(0.5)});
                for (const double s : {v - w, v, v + w}) {
                    const double g = rule.g(s), d1 = rule.g1(s) * 0.5, d2 = rule.g2(s) * 0.25 + rule.g1(s) * 0.5;
                    if (!std::isfinite(g) || !std::isfinite(d1) || !std::isfinite(d2)) continue;
                    const std::string where = rule.name + " over [" + std::to_string(a.lo) + ", " +
                                              std::to_string(a.hi) + "] at " + std::to_string(s);
                    EXPECT_TRUE(r.v.contains(g)) << where << ": value [" << r.v.lo << ", " << r.v.hi << "]";
                    EXPECT_TRUE(r.d1.contains(d1)) << where << ": d1 [" << r.d1.lo << ", " << r.d1.hi << "] ∌ " << d1;
                    EXPECT_TRUE(r.d2.contains(d2)) << where << ": d2 [" << r.d2.lo << ", " << r.d2.hi << "] ∌ " << d2;
                }
            }
        }
    }
}

TEST(Dual, ProductQuotientAndVariables) {
    const auto x = Dual<double>::variable(3.0, 0), y = Dual<double>::variable(-2.0, 1);
    const Dual<double> p = x * y, q = x / y;
    EXPECT_EQ(p.v, -6.0);
    EXPECT_EQ(p.g, (Vec3d{-2.0, 3.0, 0.0}));
    EXPECT_EQ(q.v, -1.5);
    EXPECT_DOUBLE_EQ(q.g.x, -0.5);
    EXPECT_DOUBLE_EQ(q.g.y, -0.75);  // −x / y²
    EXPECT_EQ(q.g.z, 0.0);
    // A variable exponent: d(x^y)/dy = x^y ln x.
    const auto b = Dual<double>::variable(2.0, 0), e = Dual<double>::variable(3.0, 1);
    const Dual<double> r = pow(b, e);
    EXPECT_DOUBLE_EQ(r.v, 8.0);
    EXPECT_DOUBLE_EQ(r.g.x, 12.0);
    EXPECT_DOUBLE_EQ(r.g.y, 8.0 * std::log(2.0));
}

TEST(Dual, KinksTakeTheHullOverAnInterval) {
    const auto x = Dual<Interval>::variable(Interval(-1, 2), 0);
    const Dual<Interval> a = abs(x);
    EXPECT_TRUE(a.g.x.contains(Interval(-1, 1)));
    const Dual<Interval> m = min(x, Dual<Interval>(0.5));
    EXPECT_TRUE(m.g.x.contains(Interval(0, 1)));
    // One side certainly wins: its gradient exactly.
    const Dual<Interval> n = max(x, Dual<Interval>(5.0));
    EXPECT_EQ(n.g.x.lo, 0.0);
    EXPECT_EQ(n.g.x.hi, 0.0);
}

// Where floor, tan or atan2 jump inside an interval argument, no derivative
// bounds the change: the enclosures are ℝ (the Lipschitz bound of sphere
// tracing and the monotonicity tests must not step across) — except along
// axes in which the argument does not move.
TEST(DualInterval, DerivativesAreUnboundedAcrossJumps) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto unbounded = [](const Interval& d) { return d.lo == -inf && d.hi == inf; };
    const auto moving = [](double lo, double hi) {
        return Dual<Interval>{Interval(lo, hi), {Interval(0.5), Interval(-2.0), Interval(0.0)}};
    };
    for (const Dual<Interval>& r :
         {floor(moving(0.5, 1.5)), tan(moving(1.5, 1.6)), atan2(moving(-0.5, 0.5), Dual<Interval>(-1.0))}) {
        EXPECT_TRUE(unbounded(r.g.x)) << "[" << r.g.x.lo << ", " << r.g.x.hi << "]";
        EXPECT_TRUE(unbounded(r.g.y));
        EXPECT_EQ(r.g.z.lo, 0.0);  // the argument does not move along z
        EXPECT_EQ(r.g.z.hi, 0.0);
    }
    // No jump inside: the ordinary rule, bounded.
    const Dual<Interval> calm{Interval(0.1, 0.9), {Interval(1.0), Interval(0.0), Interval(0.0)}};
    EXPECT_EQ(floor(calm).g.x.lo, 0.0);
    EXPECT_EQ(floor(calm).g.x.hi, 0.0);
    EXPECT_LT(tan(calm).g.x.hi, 3.0);
    EXPECT_LT(atan2(calm, Dual<Interval>(-1.0)).g.x.magnitude(), 1.0);  // y > 0: off the cut
    // A plain number takes the one-sided derivative.
    EXPECT_EQ(floor(Dual<double>::variable(2.0, 0)).g.x, 0.0);
    EXPECT_DOUBLE_EQ(atan2(Dual<double>::variable(0.0, 0), Dual<double>(-1.0)).g.x, -1.0);
}

TEST(JetInterval, DerivativesAreUnboundedAcrossJumps) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto line = [](double lo, double hi) {
        return Jet<Interval>{Interval(lo, hi), Interval(1.0), Interval(0.0)};
    };
    for (const Jet<Interval>& r :
         {floor(line(0.5, 1.5)), tan(line(1.5, 1.6)), atan2(line(-0.5, 0.5), Jet<Interval>(-2.0))}) {
        EXPECT_EQ(r.d1.lo, -inf);
        EXPECT_EQ(r.d1.hi, inf);
        EXPECT_EQ(r.d2.lo, -inf);
        EXPECT_EQ(r.d2.hi, inf);
    }
    const Jet<Interval> still = floor(Jet<Interval>(1.5));
    EXPECT_EQ(still.d1.hi, 0.0);
    EXPECT_EQ(still.d2.hi, 0.0);
}

TEST(Jet, LineAndProduct) {
    // H(t) = (1 + 2t)(3 − t) = 3 + 5t − 2t²: at t = 1, H = 6, H′ = 1, H″ = −4.
    const Jet<double> a = Jet<double>::line(1.0, 2.0, 1.0), b = Jet<double>::line(3.0, -1.0, 1.0);
    const Jet<double> h = a * b;
    EXPECT_EQ(h.v, 6.0);
    EXPECT_EQ(h.d1, 1.0);
    EXPECT_EQ(h.d2, -4.0);
    // (1 + 2t)/(3 − t) at t = 1: 3/2, 7/4, 7/4.
    const Jet<double> q = a / b;
    EXPECT_DOUBLE_EQ(q.v, 1.5);
    EXPECT_DOUBLE_EQ(q.d1, 1.75);
    EXPECT_DOUBLE_EQ(q.d2, 1.75);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Dual, ATieOfMinOrMaxTakesTheMiddleOfBothSlopesOrTheirHull) {
    // max(d, 0) at d = 0, as on the surface of a box's distance: not 0.
    const Dual<double> d = Dual<double>::variable(0.0, 0);
    const Dual<double> m = max(d, Dual<double>(0.0));
    EXPECT_EQ(m.v, 0.0);
    EXPECT_EQ(m.g.x, 0.5);
    const Dual<double> e = min(Dual<double>::variable(1.0, 0), Dual<double>::variable(1.0, 1));
    EXPECT_EQ(e.g, (Vec3d{0.5, 0.5, 0.0}));  // an edge of two faces: their bisector
    // Intervals enclose every subgradient.
    const Dual<Interval> a = Dual<Interval>::variable(Interval(2.0), 0), b = Dual<Interval>::variable(Interval(2.0), 1);
    const Dual<Interval> i = max(a, b);
    EXPECT_TRUE(i.g.x.contains(Interval(0.0, 1.0)));
    EXPECT_TRUE(i.g.y.contains(Interval(0.0, 1.0)));
}

}  // namespace
}  // namespace zeroset
