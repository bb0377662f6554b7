// The scene language's built-in functions (scene/builtin_functions.hpp):
// each call builds the same expression as the C++ builder it names, shapes
// take an optional point, overloads are told apart by their arguments, and
// every wrong call is an error at the call or at the argument, with the
// function's signature.
#include "zeroset/scene/builtin_functions.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "scene_test_support.hpp"
#include "zeroset/expr/deform.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/scene/expression_parser.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {
namespace {

using test::error_of;
using test::evaluate;
using test::parse;

const Expr X = var_x(), Y = var_y(), Z = var_z();

/// The surface a scene expression builds.
Expr surface(const std::string& expression) {
    return placed_objects(parse("object { surface " + expression + " }")).at(0).object().surface;
}

TEST(BuiltinFunctions, MathFunctionsEvaluateTheirFormulas) {
    const double x = 0.6, y = -1.3, z = 2.25;
    EXPECT_DOUBLE_EQ(evaluate("tan(x) + atan(y) + atan2(y, x)", x, y, z),
                     std::tan(x) + std::atan(y) + std::atan2(y, x));
    EXPECT_EQ(evaluate("floor(y) + 10*ceil(z)", x, y, z), -2.0 + 30.0);
    EXPECT_DOUBLE_EQ(evaluate("hypot(x, y)", x, y, z), std::hypot(x, y));
    EXPECT_DOUBLE_EQ(evaluate("mod(z, x)", x, y, z), z - x * std::floor(z / x));
    EXPECT_EQ(evaluate("clamp(y, -1, 1)", x, y, z), -1.0);
    EXPECT_DOUBLE_EQ(evaluate("mix(x, z, 0.25)", x, y, z), x + (z - x) * 0.25);
    EXPECT_DOUBLE_EQ(evaluate("smoothstep(0, 1, x)", x, y, z), x * x * (3 - 2 * x));
    EXPECT_EQ(surface("smooth_union(x, y, 0.5) + smooth_intersection(x, z, 0.25) - smooth_difference(y, z, 1)"),
              smooth_union(X, Y, 0.5) + smooth_intersection(X, Z, 0.25) - smooth_difference(Y, Z, 1.0));
    EXPECT_EQ(surface("algebraic_blend(x^2 + z^2 - 1, y, 0.5, 0.25)"),
              algebraic_blend(powi(X, 2) + powi(Z, 2) - 1.0, Y, 0.5, 0.25));
}

/// The constant a scene expression reads as (the parser keeps constants as doubles).
double constant_of(const std::string& text) {
    const Value value = evaluate_expression_text(text, {}, "<test>", ".");
    EXPECT_TRUE(value.is_constant()) << text;
    return value.constant();
}

/// Equal bit for bit, or both NaN.
::testing::AssertionResult same_double(double a, double b) {
    if (std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (std::isnan(a) && std::isnan(b)))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << std::hexfloat << a << " != " << b;
}

TEST(BuiltinFunctions, CallsOnConstantsFoldToTheConstantTheExpressionBuilds) {
    // The parser computes calls and operators on constants in doubles; the
    // reference is the C++ builder over Expr constants, which folds each step.
    const std::vector<double> values{-7.25, -2.0, -1.0, -0.3, 0.0, 0.5, 1.1, 2.0, 3.0, 7.0, 1e10};
    for (const double a : values) {
        const std::string sa = "(" + format_number(a) + ")";
        const Expr ea(a);
        const std::vector<std::pair<std::string, Expr>> unary{
            {"sqrt", sqrt(ea)}, {"abs", abs(ea)},     {"exp", exp(ea)},     {"log", log(ea)},
            {"sin", sin(ea)},   {"cos", cos(ea)},     {"tan", tan(ea)},     {"atan", atan(ea)},
            {"floor", floor(ea)}, {"ceil", ceil(ea)}, {"square", square(ea)}, {"-", -ea}};
        for (const auto& [f, expected] : unary)
            EXPECT_TRUE(same_double(constant_of(f + sa), expected.value())) << f << sa;
        for (const double b : values) {
            const std::string sb = "(" + format_number(b) + ")";
            const Expr eb(b);
            const std::string pair = "(" + sa + ", " + sb + ")";
            EXPECT_TRUE(same_double(constant_of("pow" + pair), pow(ea, eb).value())) << a << " ^ " << b;
            EXPECT_TRUE(same_double(constant_of(sa + " ^ " + sb), pow(ea, eb).value())) << a << " ^ " << b;
            EXPECT_TRUE(same_double(constant_of("mod" + pair), mod(ea, eb).value())) << a << " mod " << b;
            EXPECT_TRUE(same_double(constant_of("atan2" + pair), atan2(ea, eb).value()));
            EXPECT_TRUE(same_double(constant_of("hypot" + pair), hypot(ea, eb).value()));
            EXPECT_TRUE(same_double(constant_of("log_sum_exp" + pair), log_sum_exp(ea, eb).value()));
            EXPECT_TRUE(same_double(constant_of(sa + " / " + sb + " - " + sa + " * " + sb + " + " + sb),
                                    (ea / eb - ea * eb + eb).value()));
            const std::string triple = "(" + sa + ", " + sb + ", 0.75)";
            EXPECT_TRUE(same_double(constant_of("min" + triple), min(min(ea, eb), Expr(0.75)).value()));
            EXPECT_TRUE(same_double(constant_of("clamp" + triple), clamp(ea, eb, Expr(0.75)).value()));
            EXPECT_TRUE(same_double(constant_of("mix" + triple), mix(ea, eb, Expr(0.75)).value()));
            if (a != b) {
                EXPECT_TRUE(same_double(constant_of("smoothstep(" + sa + ", " + sb + ", 0.75)"),
                                        smoothstep(ea, eb, Expr(0.75)).value()));
            }
        }
    }
}

TEST(BuiltinFunctions, ShapesAndTheirPoint) {
    const ExprPoint p = coordinates();
    EXPECT_EQ(surface("sd_sphere(1.5)"), sd_sphere(p, 1.5));
    EXPECT_EQ(surface("sd_box((1, 0.5, 0.5))"), sd_box(p, {1, 0.5, 0.5}));
    EXPECT_EQ(surface("sd_round_box((1, 0.5, 0.5), 0.1)"), sd_round_box(p, {1, 0.5, 0.5}, 0.1));
    EXPECT_EQ(surface("sd_cylinder(0.5, 2)"), sd_cylinder(p, 0.5, 2));
    EXPECT_EQ(surface("sd_capped_cone(1, 0.8, 0.2)"), sd_capped_cone(p, 1, 0.8, 0.2));
    EXPECT_EQ(surface("sd_capsule((0, 0, 0), (1, 0, 0), 0.2)"), sd_capsule(p, {0, 0, 0}, {1, 0, 0}, 0.2));
    EXPECT_EQ(surface("sd_plane((0, 1, 0), -1)"), sd_plane(p, {0, 1, 0}, -1));
    EXPECT_EQ(surface("sd_ellipsoid((1, 2, 3))"), sd_ellipsoid(p, {1, 2, 3}));
    // The point argument: the shape evaluated at a hand-transformed point.
    EXPECT_EQ(surface("sd_torus(1, 0.3, (x - 2, z, y))"), sd_torus({X - 2.0, Z, Y}, 1, 0.3));
    EXPECT_EQ(surface("sd_box((1, 1, 1), (x, y, z) / 2)"), sd_box({X / 2.0, Y / 2.0, Z / 2.0}, {1, 1, 1}));
}

TEST(BuiltinFunctions, Deformations) {
    const Expr f = sd_box(coordinates(), {1, 0.5, 0.25});
    const std::string box = "sd_box((1, 0.5, 0.25))";
    EXPECT_EQ(surface("translate(" + box + ", (1, 0, -2))"), translate(f, {1, 0, -2}));
    EXPECT_EQ(surface("rotate(" + box + ", (30, 0, 90))"), rotate_degrees(f, {30, 0, 90}));
    EXPECT_EQ(surface("rotate(" + box + ", 45, (1, 1, 0))"), rotate_about(f, {1, 1, 0}, 45));
    EXPECT_EQ(surface("scale(" + box + ", 2)"), scale(f, 2.0));
    EXPECT_EQ(surface("scale(" + box + ", (1, 2, 3))"), scale(f, Vec3d{1, 2, 3}));
    EXPECT_EQ(surface("twist(" + box + ", (0, 0, 1), 0.5)"), twist(f, Twist({0, 0, 1}, 0.5)));
    EXPECT_EQ(surface("taper(" + box + ", (0, 1, 0), -0.2)"), taper(f, Taper({0, 1, 0}, -0.2)));
    EXPECT_EQ(surface("bend(" + box + ", (0, 1, 0), (1, 0, 0), 0.3)"), bend(f, Bend({0, 1, 0}, {1, 0, 0}, 0.3)));
    EXPECT_EQ(surface("bend(" + box + ", (0, 1, 0), (1, 0, 0), 0.3, 0, 1)"),
              bend(f, Bend({0, 1, 0}, {1, 0, 0}, 0.3, 0.0, 1.0)));
    // Constant parameters may be computed.
    EXPECT_EQ(surface("twist(x, (0, 0, 2) / 2, pi / 4)"), twist(X, Twist({0, 0, 1}, std::numbers::pi / 4)));
    EXPECT_DOUBLE_EQ(evaluate("rotate(x, 90, (0, 0, 1))", 0.3, 0.7, 0.0), 0.7);  // a quarter turn: x becomes y
}

TEST(BuiltinFunctions, WrongCallsAreLocatedErrors) {
    EXPECT_EQ(error_of("object { surface sd_box(1) }"),
              "scene.zs:1:25: sd_box: half_size (argument 1) must be a vector (a, b, c), but it is a number; "
              "call it as sd_box(half_size, [point])");
    EXPECT_EQ(error_of("object { surface sd_box() }"),
              "scene.zs:1:18: sd_box takes 1 or 2 arguments, but 0 were given; call it as sd_box(half_size, [point])");
    EXPECT_EQ(error_of("object { surface twist(x, (0, 0, 1), y) }"),
              "scene.zs:1:38: twist: rate (argument 3) must be a constant number, but it depends on y; "
              "call it as twist(f, axis, rate)");
    EXPECT_EQ(error_of("object { surface taper(x, (0, z, 1), 1) }"),
              "scene.zs:1:27: taper: axis (argument 2) must be a constant vector, but it depends on z; "
              "call it as taper(f, axis, rate)");
    EXPECT_EQ(error_of("object { surface rotate(x) }"),
              "scene.zs:1:18: rotate takes 2 or 3 arguments, but 1 was given; "
              "call it as rotate(f, angles) or rotate(f, angle, axis)");
    EXPECT_EQ(error_of("object { surface rotate(x, (1, 0, 0), 30) }"),
              "scene.zs:1:28: rotate: angle (argument 2) must be a number, but it is a vector; "
              "call it as rotate(f, angles) or rotate(f, angle, axis)");
    EXPECT_EQ(error_of("object { surface bend(x, (0, 1, 0), (1, 0, 0), 1, 2, 3, 4) }"),
              "scene.zs:1:18: bend takes 4 to 6 arguments, but 7 were given; "
              "call it as bend(f, along, toward, rate, [lo, hi])");
    EXPECT_EQ(error_of("object { surface translate((1, 2, 3), (1, 0, 0)) }"),
              "scene.zs:1:28: translate: f (argument 1) must be a number, but it is a vector; "
              "call it as translate(f, offset)");
    EXPECT_EQ(error_of("object { surface sd_sphere(1, 2) }"),
              "scene.zs:1:31: sd_sphere: point (argument 2) must be a point (a, b, c), but it is a number; "
              "call it as sd_sphere(radius, [point])");
    EXPECT_EQ(error_of("object { surface smooth_union(x, y, 1e308 * 10) }"),
              "scene.zs:1:37: smooth_union: k (argument 3) must be finite, but it is inf; "
              "call it as smooth_union(a, b, k)");
    // Parameter values that make no shape or no deformation: at the call.
    EXPECT_EQ(error_of("object { surface sd_sphere(-1) }"),
              "scene.zs:1:18: sd_sphere: the radius must be positive, but it is -1; "
              "call it as sd_sphere(radius, [point])");
    EXPECT_EQ(error_of("object { surface bend(x, (0, 1, 0), (0, 2, 0), 0.5) }"),
              "scene.zs:1:18: bend: the two axes must not be parallel; "
              "call it as bend(f, along, toward, rate, [lo, hi])");
    EXPECT_EQ(error_of("object { surface smooth_union(x, y, 0) }"),
              "scene.zs:1:18: smooth_union: the blend radius k must be positive; call it as smooth_union(a, b, k)");
    EXPECT_EQ(error_of("object { surface algebraic_blend(x, y, 0.5, -2) }"),
              "scene.zs:1:18: algebraic_blend: the offset b of h must be positive, but it is -2; "
              "call it as algebraic_blend(g, h, a, b)");
    EXPECT_EQ(error_of("object { surface scale(x, 0) }"),
              "scene.zs:1:18: scale: a uniform scale must be positive and finite; "
              "call it as scale(f, s) or scale(f, factors)");
    // The plain maths keep their messages.
    EXPECT_EQ(error_of("object { surface atan2(x) }"), "scene.zs:1:18: atan2 takes 2 arguments, but 1 was given");
    EXPECT_EQ(error_of("object { surface floor((x, y, z)) }"),
              "scene.zs:1:24: floor takes numbers, but argument 1 is a vector");
    // Built-in names are not for let.
    EXPECT_EQ(error_of("let twist = 1"), "scene.zs:1:5: 'twist' is a built-in name; it cannot be bound");
    EXPECT_EQ(error_of("object { surface sd_box }"), "scene.zs:1:18: 'sd_box' is a function: call it as sd_box(...)");
}

}  // namespace
}  // namespace zeroset
