// The cases every evaluator is run against (evaluators_test.cpp, and the
// batch evaluator's backends in batch_evaluator_test.cpp): a function per op
// of the op table, and composites, with the sampling they share.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset::evaluator_cases {

inline const Expr X = var_x(), Y = var_y(), Z = var_z();
// Affine functions of the coordinates; P stays in [1.25, 2.75] over [-1, 1]³.
inline const Expr L1 = 0.7 * X - 0.4 * Y + 0.3 * Z + 0.2;
inline const Expr L2 = -0.5 * X + 0.9 * Y + 0.6 * Z - 0.1;
inline const Expr P = 2.0 + 0.3 * X + 0.2 * Y - 0.25 * Z;

struct Case {
    std::string name;
    Expr f;
    double float_tolerance = 2e-5;  // relative, for the float evaluators against double
};

inline std::vector<Case> cases() {
    return {
        {"add", L1 + L2},
        {"sub", L1 - L2},
        {"mul", L1 * L2},
        {"div", L1 / P},
        {"div, pole inside", L1 / L2, 1e-1},
        {"neg", -L1},
        {"square", square(L1)},
        {"sqrt", sqrt(P)},
        {"sqrt, partly undefined", sqrt(L1), 1e-2},
        {"abs", abs(L1)},
        {"exp", exp(2.0 * L1)},
        {"log", log(P)},
        {"log, partly undefined", log(L1), 1e-2},
        {"sin", sin(3.0 * L1)},
        {"cos", cos(3.0 * L1)},
        {"powi 3", powi(L1, 3)},
        {"powi 4", powi(L1, 4)},
        {"powi 5", powi(L1, 5)},
        {"powi -1", powi(P, -1)},
        {"powi -2", powi(P, -2)},
        {"powi -3", powi(L1, -3), 1e-1},
        {"pow 2.5", pow(P, Expr(2.5))},
        {"pow -0.5", pow(P, Expr(-0.5))},
        {"pow 0.5, partly undefined", pow(L1, Expr(0.5)), 1e-2},
        // A .vm `pow` keeps an integral exponent as Pow (the builder would make powi).
        {"pow 3 as Pow", Expr::make(Op::Pow, L1, Expr(3.0))},
        {"pow 1031", pow(0.02 * L1 - 1.0, Expr(1031.0)), 1e-3},
        {"pow variable exponent", pow(P, L2)},
        {"pow variable, partly undefined", pow(L1, L2), 1e-2},
        {"tan", tan(0.8 * L1)},
        {"tan, poles inside", tan(1.5 * L1), 0.5},
        {"atan", atan(3.0 * L1)},
        {"atan2", atan2(L1, P)},
        {"atan2, cut inside", atan2(L1, L2), 1e-3},
        {"floor", floor(2.0 * L1)},
        {"hypot", hypot(L1, L2)},
        {"log-sum-exp", log_sum_exp(3.0 * L1, L2)},
        {"min", min(L1, L2)},
        {"max", max(L1, L2)},
        // Composites: shared subexpressions, CSG, nesting.
        {"sphere", sqrt(square(X) + square(Y) + square(Z)) - 0.5},
        {"csg", max(min(sqrt(square(X - 0.3) + square(Y) + square(Z)) - 0.6, abs(X) + abs(Y) + abs(Z) - 0.8),
                    -(sqrt(square(X) + square(Y + 0.2) + square(Z)) - 0.3))},
        {"blend", 1.0 - exp(-square(X - 0.4) - square(Y) - square(Z)) - exp(-square(X + 0.4) - square(Y) - square(Z))},
        {"nested", sin(X * Y) * cos(Z - X) + log(P) / sqrt(P) - powi(L2, 3) * exp(-square(L1))},
        {"norm", hypot(hypot(X, Y - 0.1), Z) + 0.2 * atan2(Y, X) + 0.1 * floor(3.0 * Z)},
    };
}

inline constexpr double lo_bound = -1.0, hi_bound = 1.0;  // the sample domain [-1, 1]³
inline constexpr int point_count = 150;                   // not a multiple of the batch width

struct Sampler {
    std::mt19937_64 rng;
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    Vec3d point() { return {uniform(lo_bound, hi_bound), uniform(lo_bound, hi_bound), uniform(lo_bound, hi_bound)}; }
};

inline bool close(double got, double want, double relative) {
    if (std::isnan(want)) return std::isnan(got);
    if (std::isinf(want)) return got == want;
    return std::abs(got - want) <= relative * (1.0 + std::abs(want));
}

}  // namespace zeroset::evaluator_cases
