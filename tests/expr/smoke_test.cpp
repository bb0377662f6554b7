#include <gtest/gtest.h>
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
using namespace zeroset;
TEST(Smoke, Sphere) {
    Expr x = var_x(), y = var_y(), z = var_z();
    Expr f = sqrt(square(x) + square(y) + square(z)) - 1.0;
    Tape tape(f);
    Evaluator<double> e(tape);
    EXPECT_NEAR(e(2, 0, 0), 1.0, 1e-15);
    Evaluator<Interval> ei(tape);
    auto r = ei(Interval(1, 2), Interval(0, 0), Interval(0, 0));
    EXPECT_LE(r.lo, 0.0); EXPECT_GE(r.hi, 1.0);
    Evaluator<Dual<Interval>> ed(tape);
    auto L = lipschitz_bound(ed, Box3{{-2,-2,-2},{2,2,2}});
    EXPECT_TRUE(L.constant >= 1.0);
    Evaluator<Jet<Interval>> ej(tape);
    Evaluator<Jet<double>> ejd(tape);
    Evaluator<Dual<double>> edd(tape);
    Evaluator<float> ef(tape);
    BatchEvaluator<float> b(tape);
}
