// The compiled ray polynomial (expr/ray_polynomial_program.hpp): the same
// coefficients as the reference walk in Polynomial arithmetic, the same
// polynomial when centred elsewhere on the ray, rounding radii that cover the
// difference, and the same refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "zeroset/expr/ray_polynomial.hpp"
#include "zeroset/expr/ray_polynomial_program.hpp"
#include "zeroset/roots/polynomial_roots.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

/// The Barth sextic (docs/algebraic-surfaces.md), φ the golden ratio.
Expr barth() {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const double p2 = phi * phi;
    const Expr x2 = square(X), y2 = square(Y), z2 = square(Z);
    return 4.0 * (p2 * x2 - y2) * (p2 * y2 - z2) * (p2 * z2 - x2) -
           (1.0 + 2.0 * phi) * square(x2 + y2 + z2 - 1.0);
}

RayPolynomialProgram compiled(const Expr& f) {
    auto c = RayPolynomialProgram::compile(Tape(f));
    EXPECT_TRUE(c.program);
    return std::move(*c.program);
}

std::vector<Ray> random_rays(int count) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3d o{3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng)};
        rays.push_back({o, normalize(Vec3d{u(rng), u(rng), u(rng)} - o * 0.3)});
    }
    return rays;
}

TEST(RayPolynomialProgram, MatchesTheReferenceWithinItsRadii) {
    const Expr torus = square(square(X) + square(Y) + square(Z) + 0.75) - 4.0 * (square(X) + square(Y));
    for (const Expr& f : {torus, barth(), powi(square(X) + 2.0 * Y - Z, 5) + X / 3.0}) {
        const Tape tape(f);
        RayPolynomialProgram program = compiled(f);
        EXPECT_EQ(program.degree(), polynomial_degree(tape));
        EXPECT_TRUE(program.error_known());
        for (const Ray& ray : random_rays(20)) {
            program.evaluate(ray, 0.0);
            const auto reference = ray_polynomial(tape, ray);
            ASSERT_TRUE(reference);
            for (int i = 0; i <= program.degree(); ++i) {
                const double difference = std::abs(program.value()[static_cast<std::size_t>(i)] - (*reference)[i]);
                EXPECT_LE(difference, 2.0 * program.radius(i)) << i;
                EXPECT_GE(program.magnitude()[static_cast<std::size_t>(i)], std::abs((*reference)[i]) * (1.0 - 1e-12));
            }
        }
    }
}

/// Σ radius_i |s|^i of the program's last evaluation.
double rounding_bound(const RayPolynomialProgram& program, double s) {
    double bound = 0.0;
    for (int i = program.degree(); i >= 0; --i) bound = bound * std::abs(s) + program.radius(i);
    return bound;
}

TEST(RayPolynomialProgram, CentringGivesTheSamePolynomialShifted) {
    RayPolynomialProgram centred = compiled(barth());
    RayPolynomialProgram direct = compiled(barth());
    for (const Ray& ray : random_rays(20)) {
        const double t_c = 2.75;
        centred.evaluate(ray, t_c);
        direct.evaluate(ray, 0.0);
        for (const double s : {-1.5, -0.2, 0.0, 0.9, 1.7}) {
            const double t = t_c + s;
            // Each is the exact F to within its rounding bound and Horner's.
            const double allowed = rounding_bound(centred, s) + horner_error_bound(centred.value(), s) +
                                   rounding_bound(direct, t) + horner_error_bound(direct.value(), t);
            EXPECT_LE(std::abs(horner(centred.value(), s).value - horner(direct.value(), t).value), allowed) << s;
        }
    }
}

/// A polynomial in t with long double coefficients (64-bit mantissa):
/// exact enough to check double radii against.
using LongPolynomial = std::vector<long double>;

LongPolynomial operator*(const LongPolynomial& a, const LongPolynomial& b) {
    LongPolynomial c(a.size() + b.size() - 1, 0.0L);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
    return c;
}

LongPolynomial operator+(LongPolynomial a, const LongPolynomial& b) {
    a.resize(std::max(a.size(), b.size()), 0.0L);
    for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
    return a;
}

LongPolynomial times(long double k, LongPolynomial a) {
    for (long double& c : a) c *= k;
    return a;
}

// A direction made from others (a camera tile's F + u·R + v·U) is off by a
// few roundings of their magnitude: compiled with room for that and given
// the magnitude, the radii cover the coefficients along the exact direction
// (the torus expanded in long double about the same centre).
TEST(RayPolynomialProgram, RadiiCoverADirectionKnownWithinItsMagnitude) {
    const Expr torus = square(square(X) + square(Y) + square(Z) + 0.75) - 4.0 * (square(X) + square(Y));
    auto c = RayPolynomialProgram::compile(Tape(torus), 16);
    ASSERT_TRUE(c.program);
    RayPolynomialProgram program = std::move(*c.program);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> w(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3d o{3.0 * w(rng), 3.0 * w(rng), -4.0 + w(rng)};
        const Vec3d f{0.1 * w(rng), 0.1 * w(rng), 1.0}, r{1.0, 0.3 * w(rng), 0.1 * w(rng)}, up{0.2 * w(rng), 1.0, 0.1 * w(rng)};
        const double u = 0.7 * w(rng), v = 0.7 * w(rng), t_c = 4.0 + w(rng);
        const Vec3d d = f + r * u + up * v;  // rounded
        Vec3d magnitude;
        for (int a = 0; a < 3; ++a)
            magnitude[a] = (std::abs(f[a]) + std::abs(u) * std::abs(r[a]) + std::abs(v) * std::abs(up[a])) * (1.0 + 1e-15);
        program.evaluate({o, d}, t_c, magnitude);
        // The exact line about t_c: x = (o + t_c·d) + s·d, d = f + u·r + v·up.
        std::array<LongPolynomial, 3> x;
        for (int a = 0; a < 3; ++a) {
            const long double exact = static_cast<long double>(f[a]) + static_cast<long double>(u) * r[a] +
                                      static_cast<long double>(v) * up[a];
            x[static_cast<std::size_t>(a)] = {static_cast<long double>(o[a]) + static_cast<long double>(t_c) * exact, exact};
        }
        const LongPolynomial sum = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + LongPolynomial{0.75L};
        const LongPolynomial exact = sum * sum + times(-4.0L, x[0] * x[0] + x[1] * x[1]);
        for (int i = 0; i <= program.degree(); ++i) {
            const long double difference = std::abs(program.value()[static_cast<std::size_t>(i)] - exact[static_cast<std::size_t>(i)]);
            EXPECT_LE(difference, static_cast<long double>(program.radius(i))) << trial << " " << i;
        }
    }
}

TEST(RayPolynomialProgram, RefusesWhatIsNotAPolynomial) {
    using Refusal = RayPolynomialProgram::Refusal;
    for (const Expr& f : {sqrt(square(X) + 1.0), X / Y, X / Expr(0.0), pow(X, Expr(0.5)), powi(X, -1), min(X, Y),
                          tan(X), atan(X), atan2(Y, X), floor(X), hypot(X, Y)}) {
        const auto c = RayPolynomialProgram::compile(Tape(f));
        EXPECT_FALSE(c.program);
        EXPECT_EQ(c.refusal, Refusal::NotPolynomial);
    }
    const auto high = RayPolynomialProgram::compile(Tape(powi(X * Y, 17)));
    EXPECT_FALSE(high.program);
    EXPECT_EQ(high.refusal, Refusal::DegreeTooHigh);
    // The limit itself (docs/limits.md): degree 32 compiles, 33 does not.
    EXPECT_TRUE(RayPolynomialProgram::compile(Tape(powi(X * Y, 16) - 1.0)).program);
    EXPECT_EQ(RayPolynomialProgram::compile(Tape(powi(X * Y, 16) * Z - 1.0)).refusal, Refusal::DegreeTooHigh);
}

TEST(RayPolynomialProgram, FoldsConstantsAndKeepsTheirBound) {
    RayPolynomialProgram program =
        compiled(square(X) / 4.0 + pow(Y, Expr(3.0)) - sqrt(Expr(2.0)) * Z + floor(Expr(2.5)) * atan(Expr(0.0)));
    EXPECT_EQ(program.degree(), 3);
    EXPECT_TRUE(program.error_known());
    program.evaluate({{0.0, 0.0, 0.0}, {2.0, 1.0, 1.0}}, 0.0);
    EXPECT_NEAR(program.value()[1], -std::sqrt(2.0), 1e-15);
    EXPECT_DOUBLE_EQ(program.value()[2], 1.0);
    EXPECT_DOUBLE_EQ(program.value()[3], 1.0);
}

}  // namespace
}  // namespace zeroset
