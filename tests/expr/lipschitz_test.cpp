// lipschitz_bound: sound (L ≥ |∇f| everywhere in the box, sampled densely)
// and not absurdly loose.
#include "zeroset/expr/lipschitz.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

struct Sampled {
    double max_gradient = 0.0;
    double min_value = INFINITY;
    double max_value = -INFINITY;
};

/// max |∇f| and the range of f over a 21³ grid of the box.
Sampled sample(const Tape& tape, const Box3& box) {
    Evaluator<Dual<double>> eval(tape);
    Sampled s;
    constexpr int n = 20;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            for (int k = 0; k <= n; ++k) {
                const Vec3d t{i / double(n), j / double(n), k / double(n)};
                const Vec3d p = box.lo + hadamard(box.size(), t);
                const Dual<double> d = evaluate_gradient(eval, p);
                if (!std::isfinite(d.v)) continue;
                s.max_gradient = std::max(s.max_gradient, length(d.g));
                s.min_value = std::min(s.min_value, d.v);
                s.max_value = std::max(s.max_value, d.v);
            }
    return s;
}

TEST(Lipschitz, BoundsTheSampledGradient) {
    const Box3 cube{{-1, -1, -1}, {1, 1, 1}};
    const Box3 offset{{0.3, -0.7, 0.1}, {1.4, 0.2, 0.9}};
    const struct {
        std::string name;
        Expr f;
        Box3 box;
    } cases[] = {
        {"plane", 3.0 * X - 4.0 * Y + 0.5, cube},
        {"product", X * Y * Z, cube},
        {"waves", sin(3.0 * X) * cos(2.0 * Y) + Z, cube},
        {"blob", 1.0 - exp(-square(X - 0.3) - square(Y) - square(Z)) - exp(-square(X + 0.3) - square(Y) - square(Z)),
         cube},
        {"csg", max(abs(X) - 0.5, min(Y * Y - Z, X + Y)), cube},
        {"reciprocal", 1.0 / (2.0 + X + 0.5 * Y), cube},
        {"sphere off the centre", sqrt(square(X) + square(Y) + square(Z)) - 1.0, offset},
        {"torus", square(sqrt(square(X) + square(Y)) - 0.7) + square(Z) - 0.04, offset},
        {"power", pow(2.0 + X, Y), cube},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<Dual<Interval>> eval(tape);
        const LipschitzBound bound = lipschitz_bound(eval, c.box);
        const Sampled s = sample(tape, c.box);
        EXPECT_GE(bound.constant, s.max_gradient);
        EXPECT_LE(bound.value.lo, s.min_value);
        EXPECT_GE(bound.value.hi, s.max_value);
        EXPECT_TRUE(std::isfinite(bound.constant));
        EXPECT_LT(bound.constant, 10.0 * s.max_gradient + 1e-9) << "L = " << bound.constant;
    }
}

TEST(Lipschitz, LinearFunctionIsExact) {
    const Tape tape(3.0 * X - 4.0 * Y + 12.0 * Z - 7.0);
    Evaluator<Dual<Interval>> eval(tape);
    const LipschitzBound bound = lipschitz_bound(eval, {{-5, -5, -5}, {5, 5, 5}});
    EXPECT_GE(bound.constant, 13.0);
    EXPECT_LE(bound.constant, 13.0 * (1 + 1e-14));
}

TEST(Lipschitz, SphereDistance) {
    const Tape tape(sqrt(square(X) + square(Y) + square(Z)) - 1.0);
    Evaluator<Dual<Interval>> eval(tape);
    // Away from the centre the interval gradient is a few times |∇f| = 1 at most.
    for (const Box3& box : {Box3{{2, -0.5, -0.5}, {3, 0.5, 0.5}}, Box3{{0.5, -1, -1}, {2, 1, 1}},
                            Box3{{-1.5, 0.8, -0.2}, {-0.4, 1.3, 0.6}}}) {
        const double l = lipschitz_bound(eval, box).constant;
        EXPECT_GE(l, 1.0);
        EXPECT_LE(l, 5.0);
    }
    const double near = lipschitz_bound(eval, {{2, -0.5, -0.5}, {3, 0.5, 0.5}}).constant;
    EXPECT_LE(near, 1.6);
    // A box around the centre, where ∇(x² + y² + z²)/(2√…) is 0/0 for intervals:
    // the bound is +∞ — sound, and the caller must subdivide or use a known constant.
    EXPECT_GE(lipschitz_bound(eval, {{-2, -2, -2}, {2, 2, 2}}).constant, 1.0);
}

TEST(Lipschitz, UndefinedPartsAreIgnoredButNotTheDefinedOnes) {
    // sqrt(x + 2) over x ∈ [-3, 1]: only x ∈ [-2, 1] counts, where |f′| is unbounded at -2.
    const Tape tape(sqrt(X + 2.0) + Y);
    Evaluator<Dual<Interval>> eval(tape);
    const LipschitzBound edge = lipschitz_bound(eval, {{-3, 0, 0}, {1, 1, 1}});
    EXPECT_EQ(edge.constant, INFINITY);
    EXPECT_LE(edge.value.lo, 0.0);  // sqrt clipped to [0, …], plus y ≥ 0
    EXPECT_GE(edge.value.lo, -1e-300);
    // Nowhere defined: an empty enclosure.
    const LipschitzBound nowhere = lipschitz_bound(eval, {{-5, 0, 0}, {-3, 1, 1}});
    EXPECT_TRUE(nowhere.value.is_empty());
    // Defined only for negative bases at an integral exponent: pow(x, 3) from a .vm file.
    const Tape cube(Expr::make(Op::Pow, X, Expr(3.0)));
    Evaluator<Dual<Interval>> eval_cube(cube);
    const LipschitzBound c = lipschitz_bound(eval_cube, {{-2, -1, -1}, {-1, 1, 1}});
    EXPECT_GE(c.constant, 12.0);  // |3x²| at x = -2
    EXPECT_LE(c.constant, 12.0 + 1e-12);
}

}  // namespace
}  // namespace zeroset
