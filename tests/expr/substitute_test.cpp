// Substitution f(X(p), Y(p), Z(p)): the result is the expression one would
// have built by hand (hash-consing), constants fold, shared nodes are rebuilt
// once, and a chain of 100 000 nodes is walked without recursion.
#include "zeroset/expr/substitute.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

TEST(Substitute, TheCoordinatesThemselvesGiveTheSameNode) {
    const Expr f = sqrt(square(X) + square(Y)) - sin(Z) * 2.0 + powi(X, 5) + pow(Y, X);
    EXPECT_EQ(substitute(f, coordinates()), f);
}

TEST(Substitute, BuildsWhatOneWouldWriteByHand) {
    const Expr f = square(X) + sin(Y) * Z - min(X, Z) / atan2(Y, X) + powi(Z, -3);
    const Expr g = substitute(f, {Y + 1.0, Z, 2.0 * X});
    EXPECT_EQ(g, square(Y + 1.0) + sin(Z) * (2.0 * X) - min(Y + 1.0, 2.0 * X) / atan2(Z, Y + 1.0) +
                     powi(2.0 * X, -3));
}

TEST(Substitute, ConstantsFoldAndIdentitiesApply) {
    const Expr f = X * 3.0 + Y * cos(Z);
    const Expr g = substitute(f, {Expr(2.0), Y, Expr(0.0)});
    EXPECT_EQ(g, 6.0 + Y);  // 2·3 folds, cos 0 = 1 folds and y·1 is y
    EXPECT_TRUE(substitute(f, {Expr(1.0), Expr(2.0), Expr(0.0)}).is_constant());
    EXPECT_EQ(substitute(f, {Expr(1.0), Expr(2.0), Expr(0.0)}).value(), 5.0);
}

TEST(Substitute, SharedNodesStayShared) {
    Expr g = X;
    for (int i = 0; i < 20; ++i) g = sin(g) + g;  // 2^20 paths, 41 nodes
    const Expr h = substitute(g, {Y, X, Z});
    EXPECT_EQ(h.node_count(), g.node_count());
    const Tape a(g), b(h);
    Evaluator<double> ea(a), eb(b);
    EXPECT_DOUBLE_EQ(eb(0.1, 0.4, 0.0), ea(0.4, 0.1, 0.0));
}

TEST(Substitute, AVeryDeepChainDoesNotRecurse) {
    Expr f = X;
    for (int i = 0; i < 100000; ++i) f = f * 0.99999 + Y;
    const Expr g = substitute(f, {Z - 1.0, Y, X});
    const Tape tf(f), tg(g);
    Evaluator<double> ef(tf), eg(tg);
    EXPECT_DOUBLE_EQ(eg(0.3, 0.001, 2.5), ef(1.5, 0.001, 0.3));
}

}  // namespace
}  // namespace zeroset
