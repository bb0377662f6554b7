// Evaluator<Complex> and Evaluator<Jet<Complex>> over every op of the op
// table: on the real axis they must agree with the double evaluators; off it,
// Jet<Complex> must give the complex derivative of H — checked by central
// differences along the real and along the imaginary direction, which agree
// only for an analytic function (the Cauchy–Riemann equations).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/complex.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();
const Expr L1 = 0.7 * X - 0.4 * Y + 0.3 * Z + 0.2;
const Expr L2 = -0.5 * X + 0.9 * Y + 0.6 * Z - 0.1;
const Expr P = 2.0 + 0.3 * X + 0.2 * Y - 0.25 * Z;  // Re P ≥ 1.25 at every sample: off the branch cuts

struct Case {
    std::string name;
    Expr f;
    bool analytic_at_samples = true;  // away from branch cuts and switching lines at the complex samples
};

std::vector<Case> cases() {
    return {
        {"add", L1 + L2},
        {"sub", L1 - L2},
        {"mul", L1 * L2},
        {"div", L1 / P},
        {"neg", -L1},
        {"square", square(L1)},
        {"sqrt", sqrt(P)},
        {"sqrt, partly undefined", sqrt(L1), false},
        {"abs", abs(P - 2.0), false},
        {"exp", exp(2.0 * L1)},
        {"log", log(P)},
        {"log, partly undefined", log(L1), false},
        {"sin", sin(3.0 * L1)},
        {"cos", cos(3.0 * L1)},
        {"powi 3", powi(L1, 3)},
        {"powi -2", powi(P, -2)},
        {"pow 2.5", pow(P, Expr(2.5))},
        {"pow 3 as Pow", Expr::make(Op::Pow, L1, Expr(3.0))},
        {"pow variable exponent", pow(P, L2)},
        {"pow variable, partly undefined", pow(L1, L2), false},
        {"tan", tan(0.8 * L1)},
        {"atan", atan(L1)},
        {"atan2", atan2(L1, P)},
        {"atan2 over x < 0", atan2(L1, L2), false},
        {"floor", floor(2.0 * L1)},
        {"hypot", hypot(P, L1)},
        {"log-sum-exp", log_sum_exp(3.0 * L1, L2)},
        {"min", min(L1, L2), false},
        {"max", max(L1, L2), false},
        {"blend", 1.0 - exp(-square(X - 0.4) - square(Y) - square(Z)) - exp(-square(X + 0.4) - square(Y) - square(Z))},
    };
}

const Vec3d origin{0.1, -0.2, 0.3};
const Vec3d direction{0.5, 0.4, -0.3};
const std::vector<double> real_ts = {-1.3, -0.6, -0.05, 0.4, 0.95, 1.6};
const std::vector<Complex> complex_ts = {{-1.1, 0.3}, {-0.2, -0.45}, {0.35, 0.2}, {0.9, -0.1}, {1.4, 0.4}};

Complex point(double o, double d, Complex t) { return Complex(o) + Complex(d) * t; }

Complex evaluate(Evaluator<Complex>& eval, Complex t) {
    return eval(point(origin.x, direction.x, t), point(origin.y, direction.y, t), point(origin.z, direction.z, t));
}

::testing::AssertionResult near(Complex a, Complex b, double tolerance) {
    const double error = std::hypot(a.re - b.re, a.im - b.im);
    if (error <= tolerance * std::max(1.0, modulus(b))) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.re << ", " << a.im << ") vs (" << b.re << ", " << b.im
                                         << "), error " << error;
}

TEST(ComplexEvaluator, RealAxisAgreesWithDoubleForEveryOp) {
    for (const Case& c : cases()) {
        const Tape tape(c.f);
        Evaluator<double> real(tape);
        Evaluator<Complex> complex(tape);
        Evaluator<Jet<double>> real_jet(tape);
        Evaluator<Jet<Complex>> complex_jet(tape);
        int compared = 0;
        for (const double t : real_ts) {
            const Vec3d p = origin + direction * t;
            const double f = real(p.x, p.y, p.z);
            if (!std::isfinite(f)) continue;  // outside the real domain: the complex value is the continuation
            ++compared;
            const Complex fc = complex(Complex(p.x), Complex(p.y), Complex(p.z));
            EXPECT_TRUE(near(fc, Complex(f), 1e-13)) << c.name << " t " << t;
            const Jet<double> h = evaluate_along_ray(real_jet, origin, direction, t);
            const Jet<Complex> hc = evaluate_along_ray(complex_jet, origin, direction, Complex(t));
            EXPECT_TRUE(near(hc.v, Complex(h.v), 1e-13)) << c.name << " t " << t;
            EXPECT_TRUE(near(hc.d1, Complex(h.d1), 1e-12)) << c.name << " t " << t;
            EXPECT_TRUE(near(hc.d2, Complex(h.d2), 1e-12)) << c.name << " t " << t;
        }
        EXPECT_GE(compared, 2) << c.name;
    }
}

TEST(ComplexEvaluator, JetIsTheComplexDerivative) {
    constexpr double step = 1e-4;
    for (const Case& c : cases()) {
        if (!c.analytic_at_samples) continue;
        const Tape tape(c.f);
        Evaluator<Complex> eval(tape);
        Evaluator<Jet<Complex>> jet(tape);
        for (const Complex t : complex_ts) {
            const Jet<Complex> h = evaluate_along_ray(jet, origin, direction, t);
            EXPECT_TRUE(near(h.v, evaluate(eval, t), 1e-14)) << c.name;
            for (const Complex dt : {Complex(step, 0.0), Complex(0.0, step)}) {
                const Complex ahead = evaluate(eval, t + dt), behind = evaluate(eval, t - dt);
                const Complex d1 = (ahead - behind) / (Complex(2.0) * dt);
                const Complex d2 = (ahead - Complex(2.0) * h.v + behind) / square(dt);
                EXPECT_TRUE(near(h.d1, d1, 1e-6)) << c.name << " at (" << t.re << ", " << t.im << ")";
                EXPECT_TRUE(near(h.d2, d2, 1e-4)) << c.name << " at (" << t.re << ", " << t.im << ")";
            }
        }
    }
}

TEST(ComplexEvaluator, AbsMinMaxFollowTheRealPartRuleWithItsDerivatives) {
    const Tape abs_tape(abs(L1)), min_tape(min(L1, L2)), max_tape(max(L1, L2));
    const Tape l1_tape(L1), l2_tape(L2);
    Evaluator<Jet<Complex>> abs_eval(abs_tape), min_eval(min_tape), max_eval(max_tape);
    Evaluator<Jet<Complex>> l1_eval(l1_tape), l2_eval(l2_tape);
    for (const Complex t : complex_ts) {
        const Jet<Complex> a = evaluate_along_ray(l1_eval, origin, direction, t);
        const Jet<Complex> b = evaluate_along_ray(l2_eval, origin, direction, t);
        const Jet<Complex> expected_abs = a.v.re >= 0.0 ? a : -a;
        const Jet<Complex> expected_min = a.v.re <= b.v.re ? a : b;
        const Jet<Complex> expected_max = a.v.re >= b.v.re ? a : b;
        const Jet<Complex> got_abs = evaluate_along_ray(abs_eval, origin, direction, t);
        const Jet<Complex> got_min = evaluate_along_ray(min_eval, origin, direction, t);
        const Jet<Complex> got_max = evaluate_along_ray(max_eval, origin, direction, t);
        for (const auto& [got, expected] : {std::pair{got_abs, expected_abs}, std::pair{got_min, expected_min},
                                            std::pair{got_max, expected_max}}) {
            EXPECT_EQ(got.v, expected.v);
            EXPECT_EQ(got.d1, expected.d1);
            EXPECT_EQ(got.d2, expected.d2);
        }
    }
}

}  // namespace
}  // namespace zeroset
