// Expressions: each parsed surface is evaluated at points and compared with
// the value computed by hand; precedence and associativity; functions;
// vectors; let; and every expression error with its exact location.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene_test_support.hpp"

namespace zeroset {
namespace {

using test::error_of;
using test::evaluate;
using test::parse;

TEST(Expression, ArithmeticMatchesHandComputedValues) {
    const double x = 0.7, y = -1.3, z = 2.1;
    EXPECT_DOUBLE_EQ(evaluate("x + 2*y - z/4", x, y, z), x + 2 * y - z / 4);
    EXPECT_DOUBLE_EQ(evaluate("(x - 1.2)^2 + y^2 + z^2 - 1", x, y, z),
                     (x - 1.2) * (x - 1.2) + y * y + z * z - 1);
    EXPECT_DOUBLE_EQ(evaluate("1 - exp(-((x-1.2)^2 + y^2 + z^2 - 1))", x, y, z),
                     1 - std::exp(-((x - 1.2) * (x - 1.2) + y * y + z * z - 1)));
    EXPECT_DOUBLE_EQ(evaluate("x*pi", x, y, z), x * std::numbers::pi);
    EXPECT_DOUBLE_EQ(evaluate("x + 1e-3 + .5", x, y, z), x + 1e-3 + 0.5);
}

TEST(Expression, PowerIsRightAssociativeAndBindsTighterThanUnaryMinus) {
    EXPECT_DOUBLE_EQ(evaluate("-x^2", 3, 0, 0), -9.0);             // -(x^2), not (-x)^2
    EXPECT_DOUBLE_EQ(evaluate("x + 2^3^2", 0, 0, 0), 512.0);        // 2^(3^2)
    EXPECT_DOUBLE_EQ(evaluate("x^2^-1", 9, 0, 0), 3.0);             // x^(2^-1) = sqrt(x)
    EXPECT_DOUBLE_EQ(evaluate("x * 2^-1", 6, 0, 0), 3.0);           // a sign after ^ is the exponent's
    EXPECT_DOUBLE_EQ(evaluate("(-x)^2", 3, 0, 0), 9.0);
    EXPECT_DOUBLE_EQ(evaluate("- -x", 3, 0, 0), 3.0);
    EXPECT_DOUBLE_EQ(evaluate("+x", 3, 0, 0), 3.0);
}

TEST(Expression, BinaryOperatorsAreLeftAssociative) {
    EXPECT_DOUBLE_EQ(evaluate("x - y - z", 10, 3, 2), 5.0);  // (10 - 3) - 2
    EXPECT_DOUBLE_EQ(evaluate("x / y / z", 12, 3, 2), 2.0);  // (12 / 3) / 2
    EXPECT_DOUBLE_EQ(evaluate("x - y * z + 1", 10, 3, 2), 5.0);
    EXPECT_DOUBLE_EQ(evaluate("x * y ^ 2", 2, 3, 0), 18.0);
}

TEST(Expression, IntegerExponentsBecomePowiAndOthersPow) {
    const Scene s = parse("object { surface x^3 + y^2.5 + z^-2 }");
    const Expr f = placed_objects(s).at(0).object().surface;
    EXPECT_EQ(f, powi(var_x(), 3) + pow(var_y(), Expr(2.5)) + powi(var_z(), -2));
    const Tape tape(f);
    Evaluator<double> eval(tape);
    EXPECT_DOUBLE_EQ(eval(-2, 4, 0.5), -8.0 + 32.0 + 4.0);  // exact sign for a negative base
}

TEST(Expression, ConstantsFold) {
    // 2*pi and friends are plain constants, so they serve as settings.
    const Scene s = parse("camera { fov 10 * pi / pi + 2^2 }");
    EXPECT_DOUBLE_EQ(s.camera.fov_degrees, 14.0);
}

TEST(Expression, Functions) {
    const double x = 0.6, y = -0.25, z = 1.7;
    EXPECT_DOUBLE_EQ(evaluate("sqrt(z) + abs(y) + exp(x)", x, y, z), std::sqrt(z) + std::abs(y) + std::exp(x));
    EXPECT_DOUBLE_EQ(evaluate("log(z) + ln(x) + sin(y) + cos(z)", x, y, z),
                     std::log(z) + std::log(x) + std::sin(y) + std::cos(z));
    EXPECT_DOUBLE_EQ(evaluate("square(y) + pow(z, x)", x, y, z), y * y + std::pow(z, x));
    EXPECT_DOUBLE_EQ(evaluate("min(x, y)", x, y, z), y);
    EXPECT_DOUBLE_EQ(evaluate("max(x, y, z, -3)", x, y, z), z);
    EXPECT_DOUBLE_EQ(evaluate("min(x, y, z, 0.1, 0.2)", 1, 2, 3), 0.1);
}

TEST(Expression, LetBindsNumbersAndExpressions) {
    const std::string lets = "let r = 0.5\nlet f = x^2 + y^2 + z^2 - r^2\nlet g = 2*f";
    EXPECT_DOUBLE_EQ(evaluate("g", 1, 1, 0, lets), 2 * (2 - 0.25));
    EXPECT_DOUBLE_EQ(evaluate("f + r", 0, 0, 0, lets), 0.25);
}

TEST(Expression, LetSharesStructureInsteadOfCopyingIt) {
    // Hash-consing: f used twice is one node, so the tape evaluates it once.
    const Scene s = parse("let f = sqrt(x^2 + y^2)\nobject { surface f * f - 1 }");
    const Expr surface = placed_objects(s).at(0).object().surface;
    EXPECT_EQ(surface.operand(0).operand(0), surface.operand(0).operand(1));
}

TEST(Expression, VectorsAndVectorArithmetic) {
    const Scene s = parse(
        "let c = (1, 2, 3)\n"
        "let d = 2 * c - (0, 1, 2) / 2 + -c * 1\n"
        "camera { from c + (0, 0, -9)  at d }");
    EXPECT_EQ(s.camera.from, (Vec3d{1, 2, -6}));
    EXPECT_EQ(s.camera.at, (Vec3d{1, 1.5, 2}));
}

TEST(Expression, UnknownIdentifier) {
    EXPECT_EQ(error_of("let a = 1\nobject {\n  surface x + q - 1\n}"), "scene.zs:3:15: unknown identifier 'q'");
    // A name is visible only after its let.
    EXPECT_EQ(error_of("let f = f + 1"), "scene.zs:1:9: unknown identifier 'f'");
}

TEST(Expression, UnknownFunctionAndNonFunctions) {
    const std::string tanh = error_of("object { surface tanh(x) }");
    EXPECT_TRUE(tanh.starts_with("scene.zs:1:18: unknown function 'tanh'; did you mean 'tan'? (the functions are sqrt, "))
        << tanh;
    EXPECT_TRUE(tanh.ends_with(", monomial and model)")) << tanh;
    EXPECT_NE(tanh.find(" sd_torus, "), std::string::npos) << tanh;
    const std::string far = error_of("object { surface frobnicate(x) }");
    EXPECT_TRUE(far.starts_with("scene.zs:1:18: unknown function 'frobnicate' (the functions are ")) << far;
    EXPECT_EQ(error_of("let radius = 1\nobject { surface x - radius2 }"),
              "scene.zs:2:22: unknown identifier 'radius2'; did you mean 'radius'?");
    EXPECT_EQ(error_of("object { surface X }"), "scene.zs:1:18: unknown identifier 'X'; did you mean 'x'?");
    EXPECT_EQ(error_of("let f = x\nobject { surface f(1) }"), "scene.zs:2:18: 'f' is not a function");
    EXPECT_EQ(error_of("object { surface x(1) }"), "scene.zs:1:18: 'x' is not a function");
    EXPECT_EQ(error_of("object { surface sqrt + 1 }"), "scene.zs:1:18: 'sqrt' is a function: call it as sqrt(...)");
}

TEST(Expression, WrongNumberOfArguments) {
    EXPECT_EQ(error_of("object { surface sqrt(x, y) }"), "scene.zs:1:18: sqrt takes 1 argument, but 2 were given");
    EXPECT_EQ(error_of("object { surface 1 + cos() }"), "scene.zs:1:22: cos takes 1 argument, but 0 were given");
    EXPECT_EQ(error_of("object { surface pow(x) }"), "scene.zs:1:18: pow takes 2 arguments, but 1 was given");
    EXPECT_EQ(error_of("object { surface min(x) }"), "scene.zs:1:18: min takes at least 2 arguments, but 1 was given");
    EXPECT_EQ(error_of("object { surface max() }"), "scene.zs:1:18: max takes at least 2 arguments, but 0 were given");
}

TEST(Expression, SyntaxErrors) {
    EXPECT_EQ(error_of("object { surface (x + 1 }"), "scene.zs:1:25: expected ')' but found '}'");
    EXPECT_EQ(error_of("object { surface sqrt(x x) }"), "scene.zs:1:25: expected ',' or ')' but found 'x'");
    EXPECT_EQ(error_of("object { surface x + }"), "scene.zs:1:22: expected an expression but found '}'");
    EXPECT_EQ(error_of("object { surface x * * y }"), "scene.zs:1:22: expected an expression but found '*'");
    EXPECT_EQ(error_of("object { surface (1, 2, 3 x) }"), "scene.zs:1:27: expected ',' or ')' but found 'x'");
    EXPECT_EQ(error_of("let a = (x + 1"), "scene.zs:1:15: expected ')' but found end of file");
}

TEST(Expression, VectorsOnlyWhereVectorsBelong) {
    EXPECT_EQ(error_of("object { surface (x, y, z) }"),
              "scene.zs:1:18: the surface must be a number (an expression in x, y, z), but found a vector");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nobject { surface x + c }"),
              "scene.zs:2:20: cannot apply '+' to a number and a vector");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nlet d = c * c"), "scene.zs:2:11: cannot apply '*' to two vectors");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nlet d = 1 / c"), "scene.zs:2:11: cannot apply '/' to a number and a vector");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nlet d = c ^ 2"), "scene.zs:2:11: cannot apply '^' to a vector and a number");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nlet d = sqrt(1, c)"),
              "scene.zs:2:17: sqrt takes numbers, but argument 2 is a vector");
    EXPECT_EQ(error_of("let c = (1, 2, 3)\nlet d = (1, c, 3)"),
              "scene.zs:2:13: a vector's components must be numbers, but component 2 is a vector");
    EXPECT_EQ(error_of("let d = (1, 2)"), "scene.zs:1:9: a vector has 3 components, but this one has 2");
    EXPECT_EQ(error_of("camera { fov (1, 2, 3) }"), "scene.zs:1:14: fov must be a number, but found a vector");
}

TEST(Expression, TooDeepNestingIsAnErrorNotACrash) {
    const std::string deep = "object { surface " + std::string(5000, '(') + "x" + std::string(5000, ')') + " }";
    EXPECT_EQ(error_of(deep), "scene.zs:1:1018: expression nested too deeply (more than 1000 levels)");
    const std::string signs = "object { surface " + std::string(5000, '-') + "x }";
    EXPECT_EQ(error_of(signs), "scene.zs:1:1018: expression nested too deeply (more than 1000 levels)");
}

}  // namespace
}  // namespace zeroset
