// Expr: hash-consing, canonical order of commutative ops, constant folding and
// the builders' small simplifications.
#include "zeroset/expr/expr.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

TEST(Expr, SameExpressionTwiceIsTheSameNode) {
    const Expr a = sqrt(square(X) + square(Y) + square(Z)) - 1.0;
    const Expr b = sqrt(square(X) + square(Y) + square(Z)) - 1.0;
    EXPECT_EQ(a.id(), b.id());
    EXPECT_TRUE(a == b);
    EXPECT_EQ(var_x().id(), X.id());
    EXPECT_EQ(Expr(2.5).id(), Expr(2.5).id());
    // Different expressions are different nodes.
    EXPECT_NE((X - Y).id(), (Y - X).id());
    EXPECT_NE(Expr(0.0).id(), Expr(-0.0).id());  // distinct constants, bit for bit
    EXPECT_NE(powi(X, 3).id(), powi(X, 4).id());
    EXPECT_NE(sin(X).id(), cos(X).id());
}

TEST(Expr, CommutativeOpsShareANode) {
    EXPECT_EQ((X + Y).id(), (Y + X).id());
    EXPECT_EQ((X * sin(Z)).id(), (sin(Z) * X).id());
    EXPECT_EQ(min(X, Y).id(), min(Y, X).id());
    EXPECT_EQ(max(X, square(Y)).id(), max(square(Y), X).id());
    EXPECT_NE((X / Y).id(), (Y / X).id());
    EXPECT_NE(pow(X, Y).id(), pow(Y, X).id());
}

TEST(Expr, TheCanonicalOrderDependsOnStructureNotOnHistory) {
    // The operand order of a commutative op decides the rounding of a
    // Taylor product, so every process must pick the same one whatever it
    // built before (a distributed render's ranks load scenes in different
    // orders). Build the same sum after different histories, the operands
    // freed in between: the written form is the same.
    const auto build = [](bool left_first) {
        Expr a, b;
        if (left_first) {
            a = sin(X * 3.0) + exp(Y), b = cos(Z * 5.0) * square(X);
        } else {
            b = cos(Z * 5.0) * square(X), a = sin(X * 3.0) + exp(Y);
        }
        return (a + b).to_string() + " | " + (a * b).to_string() + " | " + min(a, b).to_string();
    };
    const std::string first = build(true);
    for (int round = 0; round < 4; ++round) {
        std::vector<Expr> clutter;  // other nodes made in between move the allocator along
        for (int i = 0; i < 50 * round; ++i) clutter.push_back(X * static_cast<double>(i + 7));
        EXPECT_EQ(build(round % 2 == 1), first) << "round " << round;
    }
}

TEST(Expr, SharedStructureIsCountedOnce) {
    const Expr r = sqrt(square(X) + square(Y));
    const Expr f = r * r + sin(r);
    // Nodes: x, y, r (one hypot), r·r, sin r, sum.
    EXPECT_EQ(f.node_count(), 6u);
    EXPECT_EQ(X.node_count(), 1u);
}

TEST(Expr, ConstantFolding) {
    const Expr a = Expr(2.0) + Expr(3.0);
    ASSERT_TRUE(a.is_constant());
    EXPECT_EQ(a.value(), 5.0);
    EXPECT_EQ(sqrt(Expr(16.0)).value(), 4.0);
    EXPECT_EQ(powi(Expr(-2.0), 3).value(), -8.0);
    EXPECT_EQ(min(Expr(1.0), Expr(-1.0)).value(), -1.0);
    EXPECT_DOUBLE_EQ(exp(Expr(1.0)).value(), std::exp(1.0));
    EXPECT_EQ(pow(Expr(4.0), Expr(0.5)).value(), 2.0);
    EXPECT_EQ(floor(Expr(-1.5)).value(), -2.0);
    EXPECT_EQ(ceil(Expr(-1.5)).value(), -1.0);
    EXPECT_EQ(hypot(Expr(3.0), Expr(4.0)).value(), 5.0);
    EXPECT_DOUBLE_EQ(atan2(Expr(1.0), Expr(-1.0)).value(), 3 * std::atan(1.0));
    EXPECT_DOUBLE_EQ(tan(Expr(0.5)).value(), std::tan(0.5));
    EXPECT_DOUBLE_EQ(atan(Expr(2.0)).value(), std::atan(2.0));
    // Folding nests: the whole subtree collapses to one node.
    const Expr c = sin(Expr(0.5)) * cos(Expr(0.5)) + square(Expr(3.0));
    ASSERT_TRUE(c.is_constant());
    EXPECT_DOUBLE_EQ(c.value(), std::sin(0.5) * std::cos(0.5) + 9.0);
    EXPECT_EQ(c.node_count(), 1u);
    // A constant outside a function's domain folds to NaN rather than failing.
    EXPECT_TRUE(std::isnan(sqrt(Expr(-1.0)).value()));
    // Not folded: anything with a variable.
    EXPECT_FALSE((X + 1.0).is_constant());
    EXPECT_TRUE((Expr(2.0) * Expr(3.0)).is_constant_valued());
    EXPECT_FALSE(sin(X).is_constant_valued());
}

TEST(Expr, IdentitiesAreApplied) {
    EXPECT_EQ((X + 0.0).id(), X.id());
    EXPECT_EQ((0.0 + X).id(), X.id());
    EXPECT_EQ((X - 0.0).id(), X.id());
    EXPECT_EQ((X * 1.0).id(), X.id());
    EXPECT_EQ((1.0 * X).id(), X.id());
    EXPECT_EQ((X / 1.0).id(), X.id());
    EXPECT_EQ((-(-X)).id(), X.id());
    EXPECT_EQ(min(X, X).id(), X.id());
    EXPECT_EQ(max(Y, Y).id(), Y.id());
    // x·0 is not 0: for x = ∞ or NaN it is NaN.
    EXPECT_FALSE((X * 0.0).is_constant());
}

TEST(Expr, PowBecomesPowiForIntegralExponents) {
    EXPECT_EQ(pow(X, Expr(2.0)).id(), square(X).id());
    EXPECT_EQ(pow(X, Expr(3.0)).op(), Op::Powi);
    EXPECT_EQ(pow(X, Expr(3.0)).exponent(), 3);
    EXPECT_EQ(pow(X, Expr(-2.0)).exponent(), -2);
    EXPECT_EQ(pow(X, Expr(1.0)).id(), X.id());
    EXPECT_TRUE(pow(X, Expr(0.0)).is_constant());
    EXPECT_EQ(pow(X, Expr(0.0)).value(), 1.0);
    EXPECT_EQ(pow(X, Expr(2.5)).op(), Op::Pow);
    EXPECT_EQ(pow(X, Y).op(), Op::Pow);
    EXPECT_EQ(powi(X, 2).id(), square(X).id());
}

TEST(Expr, OperandsAndPrinting) {
    const Expr f = sin(X) / (Y - 2.0);
    EXPECT_EQ(f.op(), Op::Div);
    EXPECT_EQ(f.operand(0).id(), sin(X).id());
    EXPECT_EQ(f.operand(1).op(), Op::Sub);
    EXPECT_EQ(f.to_string(), "(sin(x) / (y - 2))");
    EXPECT_EQ(powi(Z, 3).to_string(), "z^3");
    EXPECT_EQ(max(X, Y).to_string().substr(0, 4), "max(");
    EXPECT_EQ(atan2(Y, X).to_string(), "atan2(y, x)");  // C's order: y first
    EXPECT_EQ(floor(tan(X)).to_string(), "floor(tan(x))");
    EXPECT_EQ(ceil(X).to_string(), "-floor(-x)");
    EXPECT_EQ(atan(X).to_string(), "atan(x)");
    EXPECT_EQ(hypot(X, Y).id(), hypot(Y, X).id());  // commutative: one node
}

TEST(Expr, NumbersAreWrittenToReadBackExactly) {
    EXPECT_EQ(number_text(0.1), "0.10000000000000001");
    EXPECT_EQ(number_text(-2.0), "-2");
    EXPECT_EQ(number_text(1e300), "1.0000000000000001e+300");
    for (const double v : {0.1, 1.0 / 3.0, -7.25e-300, 4.9e-324, 1.7976931348623157e308})
        EXPECT_EQ(std::strtod(number_text(v).c_str(), nullptr), v);
    // No literal reads as ∞ or NaN: expressions that fold to them.
    EXPECT_EQ(number_text(std::numeric_limits<double>::infinity()), "(1e308 * 10)");
    EXPECT_EQ(number_text(-std::numeric_limits<double>::infinity()), "(-1e308 * 10)");
    EXPECT_EQ(number_text(std::numeric_limits<double>::quiet_NaN()), "(0 * (1e308 * 10))");
}

TEST(Expr, PrintingADeepChainTakesNoStack) {
    // 100 000 nested calls: a recursive printer overflowed the stack here.
    constexpr int depth = 100'000;
    Expr f = X;
    for (int i = 0; i < depth; ++i) f = sin(f);
    const std::string text = f.to_string();
    ASSERT_EQ(text.size(), std::size_t{depth} * 5 + 1);  // "sin(" and ")" each level, and "x"
    EXPECT_EQ(text.substr(0, 8), "sin(sin(");
    EXPECT_EQ(text.substr(std::size_t{depth} * 4 - 4, 7), "sin(x))");
}

TEST(Expr, PrintingStopsAtItsLimitWhateverTheDagUnfoldsTo) {
    // Each level uses the one below twice: 2^60 nodes once unfolded.
    Expr f = X;
    for (int i = 0; i < 60; ++i) f = f + sin(f);
    const std::string text = f.to_string(1000);
    EXPECT_EQ(text.size(), 1000 + std::string("…").size());
    EXPECT_EQ(text.substr(1000), "…");
    EXPECT_EQ(sin(X).to_string(6), "sin(x)");  // no "…" when the text fits
    EXPECT_EQ(sin(X).to_string(5), "sin(x…");  // nor past the limit by its last piece
    std::string out = "f = ";
    EXPECT_FALSE(append_infix(out, f, {}, 50));
    EXPECT_EQ(out.size(), 50U);  // the limit counts what `out` held before
}

/// ln of a sum of exps is one log-sum-exp op (tight enclosures, no
/// overflow); a positive constant term c counts as e^ln c.
TEST(Expr, LogOfExpSumIsLogSumExp) {
    const Expr two = log(exp(X) + exp(Y));
    EXPECT_EQ(two.op(), Op::LogSumExp);
    EXPECT_EQ(two.id(), log_sum_exp(Y, X).id());
    const Expr three = log(exp(X) + (exp(2.0 * Y) + exp(Z)));
    EXPECT_EQ(Tape(three).clauses().size(), 3u);  // 2y and two log-sum-exps
    const Expr softplus = log(1.0 + exp(X));
    ASSERT_EQ(softplus.op(), Op::LogSumExp);
    EXPECT_NEAR(Evaluator<double>(Tape(softplus))(0.3, 0, 0), std::log1p(std::exp(0.3)), 1e-15);
    EXPECT_EQ(log(exp(X) + Y).op(), Op::Log);            // a term that is no exp
    EXPECT_EQ(log(exp(X) + Expr(-1.0)).op(), Op::Log);  // ln of a negative constant is no exponent
    EXPECT_EQ(log(exp(X)).op(), Op::Log);               // no sum
    // Where exp overflows the written-out form is ∞; the op is finite.
    EXPECT_NEAR(Evaluator<double>(Tape(two))(1000.0, 999.0, 0), 1000.0 + std::log1p(std::exp(-1.0)), 1e-12);
}

/// √ of a sum of squares is nested hypots: the same values, and slopes
/// bounded at the centre of a norm.
TEST(Expr, SqrtOfSquareSumIsHypot) {
    const Expr norm = sqrt(square(X) + square(Y) + square(Z - 1.0));
    EXPECT_EQ(norm.op(), Op::Hypot);
    EXPECT_NEAR(Evaluator<double>(Tape(norm))(0.3, -0.4, 2.2), std::sqrt(0.09 + 0.16 + 1.44), 1e-15);
    EXPECT_EQ(sqrt(square(X) + Y).op(), Op::Sqrt);  // a term that is no square
    EXPECT_EQ(sqrt(square(X)).op(), Op::Sqrt);      // no sum
}

TEST(Expr, OpTableNames) {
    for (int i = 0; i < op_count; ++i) {
        const auto op = static_cast<Op>(i);
        const auto found = op_from_name(op_name(op));
        ASSERT_TRUE(found.has_value()) << op_name(op);
        EXPECT_EQ(*found, op);
    }
    EXPECT_FALSE(op_from_name("frobnicate").has_value());
    EXPECT_EQ(op_arity(Op::Const), 0);
    EXPECT_EQ(op_arity(Op::Powi), 1);
    EXPECT_EQ(op_arity(Op::Max), 2);
}

TEST(Expr, UnusedNodesAreFreedAndRebuilt) {
    // Hash-consing holds nodes weakly: rebuilding after the last handle died
    // still yields a working, consistent node.
    const void* first = nullptr;
    {
        const Expr e = sin(X * 12345.678) + cos(Y);
        first = e.id();
        EXPECT_NE(first, nullptr);
    }
    for (int i = 0; i < 5000; ++i) (void)(X * static_cast<double>(i) + Y);  // churn the table, forcing sweeps
    const Expr again = sin(X * 12345.678) + cos(Y);
    EXPECT_EQ(again.id(), (sin(X * 12345.678) + cos(Y)).id());
    EXPECT_EQ(again.operand(0).op() == Op::Sin ? again.operand(0).operand(0).op() : again.operand(1).operand(0).op(),
              Op::Mul);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(ExprLifetime, DestroyingAVeryDeepChainDoesNotOverflowTheStack) {
    {
        Expr e = var_x();
        for (int i = 0; i < 200000; ++i) e = sin(e) + Expr(static_cast<double>(i));
        EXPECT_GT(e.node_count(), 200000u);
    }  // destroyed here: recursion would need ~400 000 nested destructor frames
    EXPECT_EQ(Expr(2.0) * var_x(), var_x() * Expr(2.0));  // the interning table still works afterwards
}

}  // namespace
}  // namespace zeroset
