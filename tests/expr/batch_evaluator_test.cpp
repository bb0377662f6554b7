// The batch evaluator (expr/batch_evaluator.hpp) at every SIMD level
// Highway compiled that this CPU runs, against the scalar evaluators: every
// case of the op table, constants on either side of every kind of op, edge
// values, partial batches, and rebinding between pruned tapes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <hwy/targets.h>

#include "evaluator_cases.hpp"
#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {
namespace {

using namespace evaluator_cases;

/// The batch evaluator at every SIMD level Highway compiled that this CPU
/// runs (expr/batch_lanes.hpp), each against the scalar evaluators.
class BatchBackends : public ::testing::TestWithParam<std::int64_t> {
protected:
    void SetUp() override { hwy::SetSupportedTargetsForTest(GetParam()); }
    void TearDown() override { hwy::SetSupportedTargetsForTest(0); }  // back to the CPU's own
};

INSTANTIATE_TEST_SUITE_P(Targets, BatchBackends, ::testing::ValuesIn(hwy::SupportedAndGeneratedTargets()),
                         [](const ::testing::TestParamInfo<std::int64_t>& target) {
                             return std::string(hwy::TargetName(target.param));
                         });

TEST_P(BatchBackends, RunAtTheirTarget) { EXPECT_EQ(batch_simd_target(), hwy::TargetName(GetParam())); }

TEST_P(BatchBackends, PlainAndBatchAgree) {
    Sampler sampler{std::mt19937_64(1)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<float> eval_f(tape);
        BatchEvaluator<double> batch(tape);
        BatchEvaluator<float> batch_f(tape);
        std::vector<double> x(point_count), y(point_count), z(point_count), out(point_count);
        std::vector<float> xf(point_count), yf(point_count), zf(point_count), out_f(point_count);
        for (int i = 0; i < point_count; ++i) {
            const Vec3d p = sampler.point();
            xf[i] = static_cast<float>(p.x);
            yf[i] = static_cast<float>(p.y);
            zf[i] = static_cast<float>(p.z);
            // The double evaluators see the very same (float) coordinates.
            x[i] = xf[i];
            y[i] = yf[i];
            z[i] = zf[i];
        }
        batch.evaluate(x, y, z, out);
        batch_f.evaluate(xf, yf, zf, out_f);
        int defined = 0;
        for (int i = 0; i < point_count; ++i) {
            const double d = eval(x[i], y[i], z[i]);
            const float f = eval_f(xf[i], yf[i], zf[i]);
            ASSERT_TRUE(close(out[i], d, 1e-15)) << "batch<double> " << out[i] << " vs " << d << " at point " << i;
            ASSERT_TRUE(close(out_f[i], f, 1e-6)) << "batch<float> " << out_f[i] << " vs " << f << " at point " << i;
            if (std::isnan(d)) continue;
            ++defined;
            ASSERT_TRUE(close(f, d, c.float_tolerance))
                << "float " << f << " vs double " << d << " at (" << x[i] << ", " << y[i] << ", " << z[i] << ")";
        }
        EXPECT_GT(defined, point_count / 4);
    }
}

/// Points evenly along the segment from `from` to `to`, in float, and the
/// same floats as doubles (the double evaluators see the very same points).
struct LinePoints {
    std::vector<double> x, y, z;
    std::vector<float> xf, yf, zf;
};
LinePoints points_along(const Vec3d& from, const Vec3d& to) {
    LinePoints p;
    for (int i = 0; i < point_count; ++i) {
        const Vec3d q = from + (to - from) * (static_cast<double>(i) / point_count);
        p.xf.push_back(static_cast<float>(q.x));
        p.yf.push_back(static_cast<float>(q.y));
        p.zf.push_back(static_cast<float>(q.z));
        p.x.push_back(p.xf.back());
        p.y.push_back(p.yf.back());
        p.z.push_back(p.zf.back());
    }
    return p;
}

/// The batch evaluators, bound to `tape`, give the scalar evaluators' values at the points.
void expect_batches_match_scalar(BatchEvaluator<double>& batch, BatchEvaluator<float>& batch_f, const Tape& tape,
                                 const LinePoints& p) {
    Evaluator<double> eval(tape);
    Evaluator<float> eval_f(tape);
    std::vector<double> out(p.x.size());
    std::vector<float> out_f(p.x.size());
    batch.evaluate(p.x, p.y, p.z, out);
    batch_f.evaluate(p.xf, p.yf, p.zf, out_f);
    for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_TRUE(close(out[i], eval(p.x[i], p.y[i], p.z[i]), 1e-15)) << "double at point " << i;
        ASSERT_TRUE(close(out_f[i], eval_f(p.xf[i], p.yf[i], p.zf[i]), 1e-6)) << "float at point " << i;
    }
}

/// Constants are broadcast, never spread over lanes, except for the ops
/// that read lanes one by one: a constant on either side of every binary
/// op, into the vector functions' fallbacks, and a tape that is a constant.
TEST_P(BatchBackends, ConstantOperandsOnEitherSide) {
    const Expr c(0.375);
    const std::vector<std::pair<std::string, Expr>> functions = {
        {"c + x", c + X},       {"x - c", X - c},           {"c - x", c - X},
        {"c / x", c / X},       {"x / c", X / c},           {"min(c, x)", min(c, X)},
        {"max(x, c)", max(X, c)}, {"hypot(x, c)", hypot(X, c)}, {"hypot(c, y)", hypot(c, Y)},
        {"lse(c, x)", log_sum_exp(c, 3.0 * X)}, {"lse(x, c)", log_sum_exp(3.0 * X, c)},
        {"atan2(c, x)", atan2(c, X)}, {"pow(c, x)", pow(c, X)}, {"pow(x + 2, c)", pow(X + 2.0, c)},
        {"a constant", Expr(-1.5)},
    };
    const LinePoints points = points_along({-1.0, 0.5, 0.25}, {1.0, -0.5, 0.25});
    for (const auto& [name, f] : functions) {
        SCOPED_TRACE(name);
        const Tape tape(f);
        BatchEvaluator<double> batch(tape);
        BatchEvaluator<float> batch_f(tape);
        ASSERT_NO_FATAL_FAILURE(expect_batches_match_scalar(batch, batch_f, tape, points));
    }
}

/// Constants reach ops the expression builder would have folded only in
/// pruned tapes: a unary op or a vector function of a constant, two
/// constants into one op. Each function below prunes, over its box, to such
/// a tape; the batch over it (bound by rebind, as the slice binds its
/// leaves) must give the scalar evaluator's values.
TEST_P(BatchBackends, PrunedTapesFeedConstantsToEveryKindOfOp) {
    const Box3 box{{1.0, 1.0, -1.0}, {2.0, 2.0, 1.0}};  // x, y in [1, 2]
    const std::vector<std::pair<std::string, Expr>> functions = {
        {"exp of a constant", exp(min(X, Expr(-1.0))) + Z},
        {"sin of a constant", sin(max(Y, Expr(3.0))) * Z},
        {"log of a constant", log(max(X, Expr(5.0))) - Z},
        {"atan of a constant", atan(min(Y, Expr(0.5))) + Z},
        {"neg of a constant", -min(X, Expr(0.25)) + Z},
        {"powi of a constant", powi(min(Y, Expr(0.5)), 3) + Z},
        {"tan of a constant", tan(min(X, Expr(0.5))) + Z},
        {"two constants", min(X, Expr(0.5)) * max(Y, Expr(4.0)) + Z},
        {"hypot of two constants", hypot(min(X, Expr(0.5)), max(Y, Expr(4.0))) + Z},
        {"only a constant left", min(X, Expr(-3.0))},
    };
    const LinePoints points = points_along({1.0, 2.0, -1.0}, {2.0, 1.0, 1.0});
    BatchEvaluator<double> batch;  // bound to each pruned tape in turn
    BatchEvaluator<float> batch_f;
    for (const auto& [name, f] : functions) {
        SCOPED_TRACE(name);
        const Tape full(f);
        TapePruner pruner(full);
        Tape pruned;
        pruner.prune(full, box, pruned);
        ASSERT_LT(pruned.clauses().size(), full.clauses().size());
        batch.rebind(pruned);
        batch_f.rebind(pruned);
        ASSERT_NO_FATAL_FAILURE(expect_batches_match_scalar(batch, batch_f, pruned, points));
    }
}

/// Lanes outside the vector functions' ranges, NaN and ±∞ behave as the
/// scalar functions do: overflow to ∞, log of 0 and of negatives, huge
/// arguments of sin and cos, NaN through min and max from either side.
TEST_P(BatchBackends, EdgeValuesMatchTheScalarFunctions) {
    const std::vector<double> edges = {0.0, -0.0, 1e-320, -1e-320, 1e-40, 1.0, -1.0, 88.0, 89.0, 100.0, 200.0,
                                       710.0, 800.0, -800.0, 38999.0, 39001.0, -1e6, 1e30, -1e30,
                                       std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::quiet_NaN()};
    const std::vector<std::pair<std::string, Expr>> ops = {
        {"exp", exp(X)}, {"log", log(X)}, {"sin", sin(X)}, {"cos", cos(X)}, {"atan", atan(X)}, {"sqrt", sqrt(X)},
        {"min", min(X, Y)}, {"max", max(X, Y)}, {"min swapped", min(Y, X)}, {"max swapped", max(Y, X)},
        {"div", X / Y}, {"powi -3", powi(X, -3)}, {"floor", floor(X)}, {"abs", abs(X)},
        {"log-sum-exp", log_sum_exp(X, Y)}, {"log-sum-exp swapped", log_sum_exp(Y, X)}, {"hypot", hypot(X, Y)},
        {"hypot of tiny", hypot(X * 1e-300, Y * 1e-300)}};
    for (const auto& [name, f] : ops) {
        SCOPED_TRACE(name);
        const Tape tape(f);
        Evaluator<double> eval(tape);
        Evaluator<float> eval_f(tape);
        BatchEvaluator<double> batch(tape);
        BatchEvaluator<float> batch_f(tape);
        std::vector<double> x, y, z, out;
        for (const double a : edges) {
            for (const double b : {0.5, -2.0, std::numeric_limits<double>::quiet_NaN()}) {
                x.push_back(a);
                y.push_back(b);
                z.push_back(0.0);
            }
        }
        out.resize(x.size());
        std::vector<float> xf(x.begin(), x.end()), yf(y.begin(), y.end()), zf(z.begin(), z.end()), out_f(x.size());
        batch.evaluate(x, y, z, out);
        batch_f.evaluate(xf, yf, zf, out_f);
        for (std::size_t i = 0; i < x.size(); ++i) {
            EXPECT_TRUE(close(out[i], eval(x[i], y[i], 0.0), 1e-15))
                << "double at " << x[i] << ", " << y[i] << ": " << out[i] << " vs " << eval(x[i], y[i], 0.0);
            EXPECT_TRUE(close(out_f[i], eval_f(xf[i], yf[i], 0.0f), 1e-6))
                << "float at " << xf[i] << ", " << yf[i] << ": " << out_f[i] << " vs " << eval_f(xf[i], yf[i], 0.0f);
        }
    }
}

TEST(Evaluators, BatchHandlesEmptyAndPartialBatches) {
    const Tape tape(sin(X) * Y + Z);
    BatchEvaluator<double> batch(tape);
    Evaluator<double> eval(tape);
    std::vector<double> none;
    batch.evaluate(none, none, none, none);  // nothing to do, nothing touched
    for (const std::size_t n : {std::size_t{1}, BatchEvaluator<double>::lanes, BatchEvaluator<double>::lanes + 1}) {
        std::vector<double> x(n), y(n), z(n), out(n, -1.0);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = 0.01 * static_cast<double>(i);
            y[i] = 2.0;
            z[i] = -static_cast<double>(i);
        }
        batch.evaluate(x, y, z, out);
        for (std::size_t i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(out[i], eval(x[i], y[i], z[i])) << "n = " << n;
    }
}

TEST(Evaluators, BatchRebindsBetweenPrunedTapesKeepEveryConstantRight) {
    // Two balls pruned apart: each pruned tape has its own constants, in
    // slots the other uses for working values or other constants. Going back
    // and forth, a rebind refills only what changed; the values must stay
    // those of a fresh evaluator every time.
    const auto ball = [](double cx, double r) { return hypot(hypot(X - cx, Y), Z) - r; };
    const Tape full(min(ball(-5.0, 1.0), 3.0 * ball(5.0, 2.0)));
    TapePruner pruner(full);
    const Box3 left{{-6, -1, -1}, {-4, 1, 1}}, right{{4, -1, -1}, {6, 1, 1}};
    Tape near_left, near_right;
    pruner.prune(full, left, near_left);
    pruner.prune(full, right, near_right);
    ASSERT_LT(near_left.clauses().size(), full.clauses().size());
    ASSERT_LT(near_right.clauses().size(), full.clauses().size());
    BatchEvaluator<float> batch(full);
    Evaluator<double> reference(full);
    std::vector<float> x(7), y(7), z(7), out(7);
    for (int round = 0; round < 6; ++round) {
        // Round 4 takes the full tape, whose constants the pruned tapes' working values overwrote.
        const bool on_left = round % 2 == 1;
        batch.rebind(round == 4 ? full : on_left ? near_left : near_right);
        for (std::size_t i = 0; i < x.size(); ++i) {
            x[i] = static_cast<float>((on_left ? -5.0 : 5.0) + 0.1 * static_cast<double>(i));
            y[i] = 0.25f;
            z[i] = -0.5f;
        }
        batch.evaluate(x, y, z, out);
        for (std::size_t i = 0; i < x.size(); ++i)
            EXPECT_NEAR(out[i], reference(x[i], y[i], z[i]), 1e-5) << "round " << round << ", point " << i;
    }
}


}  // namespace
}  // namespace zeroset
