// The named algebraic surfaces (docs/algebraic-surfaces.md): each evaluates to
// its documented equation, written out again here independently of the
// builders; the point argument and defaults work; wrong calls are located
// errors; and every scene in scenes/algebraic/ renders with sensible coverage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "scene/scene_test_support.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/algebraic_surfaces.hpp"

namespace zeroset {
namespace {

using test::error_of;
using test::evaluate;
using Formula = std::function<double(double, double, double)>;

constexpr double phi = 1.6180339887498949;  // (1 + √5)/2
constexpr double sqrt2 = 1.4142135623730951;

double p2(double v) { return v * v; }
double p3(double v) { return v * v * v; }
double p4(double v) { return p2(p2(v)); }

double chebyshev8(double t) { return 128 * std::pow(t, 8) - 256 * std::pow(t, 6) + 160 * p4(t) - 32 * p2(t) + 1; }

struct Case {
    std::string call;  // as written in a scene
    Formula expected;
};

std::vector<Case> cases() {
    return {
        {"ellipsoid(2, 1, 0.5)", [](double x, double y, double z) { return x * x / 4 + y * y + z * z / 0.25 - 1; }},
        {"cylinder(0.5)", [](double x, double y, double) { return x * x + y * y - 0.25; }},
        {"cone(2)", [](double x, double y, double z) { return x * x + y * y - 4 * z * z; }},
        {"paraboloid(3)", [](double x, double y, double z) { return x * x + y * y - 3 * z; }},
        {"hyperboloid(2, 3, 1)", [](double x, double y, double z) { return (x * x + y * y) / 4 - z * z / 9 - 1; }},
        {"hyperboloid(2, 3, 2)", [](double x, double y, double z) { return (x * x + y * y) / 4 - z * z / 9 + 1; }},
        {"torus(2, 0.5)",
         [](double x, double y, double z) { return p2(x * x + y * y + z * z + 4 - 0.25) - 16 * (x * x + y * y); }},
        {"steiner()",
         [](double x, double y, double z) { return x * x * y * y + y * y * z * z + z * z * x * x - x * y * z; }},
        {"kummer(1.69)",
         [](double x, double y, double z) {
             const double lambda = (3 * 1.69 - 1) / (3 - 1.69);
             return p2(x * x + y * y + z * z - 1.69) - lambda * (1 - z - sqrt2 * x) * (1 - z + sqrt2 * x) *
                                                           (1 + z + sqrt2 * y) * (1 + z - sqrt2 * y);
         }},
        {"clebsch()",
         [](double x, double y, double z) {
             return 81 * (p3(x) + p3(y) + p3(z)) -
                    189 * (x * x * y + x * x * z + y * y * x + y * y * z + z * z * x + z * z * y) + 54 * x * y * z +
                    126 * (x * y + x * z + y * z) - 9 * (x * x + y * y + z * z) - 9 * (x + y + z) + 1;
         }},
        {"barth_sextic()",
         [](double x, double y, double z) {
             const double f2 = phi * phi;
             return (1 + 2 * phi) * p2(x * x + y * y + z * z - 1) -
                    4 * (f2 * x * x - y * y) * (f2 * y * y - z * z) * (f2 * z * z - x * x);
         }},
        {"chmutov_octic()",
         [](double x, double y, double z) { return chebyshev8(x) + chebyshev8(y) + chebyshev8(z) + 1; }},
        {"endrass_octic()",
         [](double x, double y, double z) {
             const double r = x * x + y * y;
             const double q = -4 * (1 + sqrt2) * r * r + (8 * (2 + sqrt2) * z * z + 2 * (2 + 7 * sqrt2)) * r -
                              16 * p4(z) + 8 * (1 - 2 * sqrt2) * z * z - (1 + 12 * sqrt2);
             return q * q - 64 * (x * x - 1) * (y * y - 1) * (p2(x + y) - 2) * (p2(x - y) - 2);
         }},
        {"tangle_cube()",
         [](double x, double y, double z) {
             return p4(x) - 5 * x * x + p4(y) - 5 * y * y + p4(z) - 5 * z * z + 11.8;
         }},
        {"piriform()", [](double x, double y, double z) { return p4(x) - p3(x) + y * y + z * z; }},
        {"lemniscate_of_gerono()", [](double x, double y, double z) { return p4(x) - x * x + y * y + z * z; }},
        {"monkey_saddle()", [](double x, double y, double z) { return z - p3(x) + 3 * x * y * y; }},
        {"monomial(-3, 2, 0, 5)", [](double x, double, double z) { return -3 * x * x * std::pow(z, 5); }},
    };
}

const double samples[][3] = {{0, 0, 0},    {1, 0, 0},          {0.3, -0.7, 0.2}, {-1.1, 0.4, 0.9},
                             {0.5, 0.5, 0.5}, {2.2, -1.3, -0.6}, {-0.25, 1.7, -1.4}};

TEST(AlgebraicSurfaces, EachEvaluatesToItsDocumentedEquation) {
    for (const Case& c : cases()) {
        for (const auto& p : samples) {
            const double want = c.expected(p[0], p[1], p[2]);
            EXPECT_NEAR(evaluate(c.call, p[0], p[1], p[2]), want, 1e-10 * std::max(1.0, std::abs(want)))
                << c.call << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
        }
    }
}

TEST(AlgebraicSurfaces, KnownPointsLieOnTheSurfaces) {
    EXPECT_DOUBLE_EQ(evaluate("torus(1, 0.35)", 1.35, 0, 0), 0);         // outer equator
    EXPECT_DOUBLE_EQ(evaluate("clebsch()", 1.0 / 3, 1.0 / 3, 1.0 / 3), 0);  // fixed by permuting x, y, z
    EXPECT_NEAR(evaluate("piriform()", 0.75, std::sqrt(27.0 / 256), 0), 0, 1e-15);
    // A node of the Chmutov octic: T8 = +1, -1, -1 at cos(2pi/8), cos(pi/8), cos(3pi/8).
    const double pi = 3.141592653589793;
    EXPECT_NEAR(evaluate("chmutov_octic()", std::cos(pi / 4), std::cos(pi / 8), std::cos(3 * pi / 8)), 0, 1e-12);
    EXPECT_LT(evaluate("torus(1, 0.35)", 1, 0, 0), 0);  // inside the tube
    EXPECT_GT(evaluate("torus(1, 0.35)", 0, 0, 0), 0);  // in the hole
}

TEST(AlgebraicSurfaces, OmittedParametersTakeTheirDefaults) {
    for (const AlgebraicSurface& s : algebraic_surfaces()) {
        std::string full = std::string(s.name) + "(";
        for (std::size_t i = 0; i < s.parameters.size(); ++i)
            full += (i ? ", " : "") + std::to_string(s.parameters[i].default_value);
        full += ")";
        const std::string bare = std::string(s.name) + "()";
        // "x + …": monomial() is the constant 1, which is no surface on its own.
        EXPECT_NEAR(evaluate("x + " + bare, 0.3, -0.4, 0.7), evaluate("x + " + full, 0.3, -0.4, 0.7), 1e-12) << full;
    }
    EXPECT_DOUBLE_EQ(evaluate("ellipsoid(2)", 1, 1, 1), 0.25 + 1 + 1 - 1);  // b = c = 1
}

TEST(AlgebraicSurfaces, APointArgumentEvaluatesThereSoTransformsCompose) {
    const double x = 0.4, y = -0.3, z = 1.2;
    EXPECT_DOUBLE_EQ(evaluate("torus(1, 0.3, (x - 2, z, y))", x, y, z),
                     p2(p2(x - 2) + z * z + y * y + 1 - 0.09) - 4 * (p2(x - 2) + z * z));
    EXPECT_DOUBLE_EQ(evaluate("steiner((2*x, y, z))", x, y, z), evaluate("steiner()", 2 * x, y, z));
    EXPECT_DOUBLE_EQ(evaluate("min(ellipsoid(1, 1, 1, p), cylinder(0.2))", x, y, z, "let p = (x, y, z - 1)"),
                     std::min(x * x + y * y + p2(z - 1) - 1, x * x + y * y - 0.04));
}

/// Degree in x, y, z of a polynomial Expr (division by constants only).
int degree(const Expr& e) {
    switch (e.op()) {
        case Op::Const: return 0;
        case Op::VarX:
        case Op::VarY:
        case Op::VarZ: return 1;
        case Op::Add:
        case Op::Sub: return std::max(degree(e.operand(0)), degree(e.operand(1)));
        case Op::Mul: return degree(e.operand(0)) + degree(e.operand(1));
        case Op::Div: return e.operand(1).is_constant() ? degree(e.operand(0)) : -1000;
        case Op::Neg: return degree(e.operand(0));
        case Op::Square: return 2 * degree(e.operand(0));
        case Op::Powi: return e.exponent() * degree(e.operand(0));
        default: return -1000;  // not a polynomial
    }
}

TEST(AlgebraicSurfaces, AreRealPolynomialsOfTheDocumentedDegree) {
    const ExprVector p{var_x(), var_y(), var_z()};
    for (const AlgebraicSurface& s : algebraic_surfaces()) {
        if (s.degree < 0) continue;  // monomial: its degree is i + j + k
        EXPECT_EQ(degree(build_algebraic_surface(s, {}, p)), s.degree) << s.name;
    }
    const double args[] = {2, 3, 1, 4};
    EXPECT_EQ(degree(build_algebraic_surface(*find_algebraic_surface("monomial"), args, p)), 8);
}

TEST(AlgebraicSurfaces, WrongCallsAreLocatedErrorsThatShowTheSignature) {
    EXPECT_EQ(error_of("object { surface torus(1, 2, 3) }"),
              "scene.zs:1:18: torus takes at most 2 numbers and a point, but 3 numbers were given; "
              "call it as torus(R = 1, r = 0.35, [point])");
    EXPECT_EQ(error_of("object { surface steiner(1) }"),
              "scene.zs:1:18: steiner takes at most 0 numbers and a point, but 1 number was given; "
              "call it as steiner([point])");
    EXPECT_EQ(error_of("object {\n  surface torus(1, -2) }"),
              "scene.zs:2:11: torus: r must be positive, but it is -2; call it as torus(R = 1, r = 0.35, [point])");
    EXPECT_EQ(error_of("object { surface cone((1, 2, 3), 2) }"),
              "scene.zs:1:23: cone takes the point (a vector) only as its last argument, but argument 1 is a "
              "vector; call it as cone(k = 1, [point])");
    EXPECT_EQ(error_of("object { surface cylinder(x) }"),
              "scene.zs:1:27: cylinder parameter r must be a constant number, but it depends on x");
    EXPECT_EQ(error_of("object { surface hyperboloid(1, 1, 3) }"),
              "scene.zs:1:18: hyperboloid: sheets must be 1 or 2, but it is 3; "
              "call it as hyperboloid(a = 1, c = 1, sheets = 1, [point])");
    EXPECT_EQ(error_of("object { surface kummer(3) }"),
              "scene.zs:1:18: kummer: mu2 must be between 1/3 and 3 (16 real nodes), but it is 3; "
              "call it as kummer(mu2 = 1.69, [point])");
    EXPECT_EQ(error_of("object { surface monomial(1, 64) }"), "");  // the limit (docs/limits.md)
    EXPECT_EQ(error_of("object { surface monomial(1, 65) }"),
              "scene.zs:1:18: monomial: i must be an integer from 0 to 64, but it is 65; "
              "call it as monomial(c = 1, i = 0, j = 0, k = 0, [point])");
    EXPECT_EQ(error_of("object { surface monomial(1, 2.5) }"),
              "scene.zs:1:18: monomial: i must be an integer from 0 to 64, but it is 2.5; "
              "call it as monomial(c = 1, i = 0, j = 0, k = 0, [point])");
    EXPECT_EQ(error_of("object { surface clebsch }"),
              "scene.zs:1:18: 'clebsch' is a function: call it as clebsch(...)");
    EXPECT_EQ(error_of("let torus = 1"), "scene.zs:1:5: 'torus' is a built-in name; it cannot be bound");
    EXPECT_EQ(error_of("object { surface torus(1, 0.3 }"), "scene.zs:1:31: expected ',' or ')' but found '}'");
}

/// Where the pixels differ from the background, as a mask.
std::vector<bool> covered_pixels(const Image& image) {
    const Vec3f bg = image.at(0, 0);
    std::vector<bool> mask;
    for (const auto& p : image.pixels) mask.push_back(std::abs(p.x - bg.x) + std::abs(p.y - bg.y) + std::abs(p.z - bg.z) > 1e-3f);
    return mask;
}

/// The fraction of pixels that differ from the background.
double coverage(const Image& image) {
    const std::vector<bool> mask = covered_pixels(image);
    return static_cast<double>(std::ranges::count(mask, true)) / static_cast<double>(mask.size());
}

TEST(AlgebraicSurfaces, EverySceneRendersWithSensibleCoverage) {
    namespace fs = std::filesystem;
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/algebraic")) {
        if (entry.path().extension() != ".zs") continue;
        ++scenes;
        RenderSettings settings;
        settings.width = 48;
        settings.height = 36;
        const double c = coverage(render(load_scene(entry.path()), settings).image);
        EXPECT_GT(c, 0.05) << entry.path();
        EXPECT_LT(c, 0.9) << entry.path();
    }
    EXPECT_GE(scenes, 17);
}

TEST(AlgebraicSurfaces, EverySolverSeesWhatTheIntervalMethodSees) {
    // The interval method shares no root finding with the polynomial solvers:
    // their images must cover the same pixels (up to a few silhouette pixels,
    // where a ray grazes the surface closer than either can resolve).
    namespace fs = std::filesystem;
    for (const auto& entry : fs::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/algebraic")) {
        const Scene scene = load_scene(entry.path());
        RenderSettings settings;
        settings.width = 40;
        settings.height = 30;
        settings.method = Method::Interval;
        const std::vector<bool> reference = covered_pixels(render(scene, settings).image);
        settings.method = Method::Polynomial;
        for (const PolynomialSolver solver : all_polynomial_solvers()) {
            SCOPED_TRACE(entry.path().stem().string() + " / " + std::string(polynomial_solver_name(solver)));
            settings.solver = solver;
            const std::vector<bool> mask = covered_pixels(render(scene, settings).image);
            const auto differing = std::inner_product(mask.begin(), mask.end(), reference.begin(), 0, std::plus<>(),
                                                      std::not_equal_to<>());
            EXPECT_LE(differing, 3);
        }
    }
}

}  // namespace
}  // namespace zeroset
