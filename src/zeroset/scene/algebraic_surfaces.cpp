// The table of named algebraic surfaces; equations and sources are in
// docs/algebraic-surfaces.md. Every builder is written on the point p, not on
// x, y, z, so a surface can be evaluated at a hand-transformed point.
#include "zeroset/scene/algebraic_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

using Values = std::span<const double>;

Expr sq(const Expr& e) { return square(e); }

/// "" when every value is > 0, else a message naming the first that is not.
template <std::size_t N>
std::string all_positive(Values v, const char* const (&names)[N]) {
    for (std::size_t i = 0; i < N; ++i) {
        if (!(v[i] > 0)) return std::string(names[i]) + " must be positive, but it is " + format_number(v[i]);
    }
    return "";
}

std::string no_check(Values) { return ""; }

Expr ellipsoid(const ExprVector& p, Values v) {
    return sq(p[0]) / (v[0] * v[0]) + sq(p[1]) / (v[1] * v[1]) + sq(p[2]) / (v[2] * v[2]) - 1.0;
}

Expr cylinder(const ExprVector& p, Values v) { return sq(p[0]) + sq(p[1]) - v[0] * v[0]; }

Expr cone(const ExprVector& p, Values v) { return sq(p[0]) + sq(p[1]) - v[0] * v[0] * sq(p[2]); }

Expr paraboloid(const ExprVector& p, Values v) { return sq(p[0]) + sq(p[1]) - v[0] * p[2]; }

// One sheet: (x² + y²)/a² − z²/c² − 1; two sheets: … + 1.
Expr hyperboloid(const ExprVector& p, Values v) {
    return (sq(p[0]) + sq(p[1])) / (v[0] * v[0]) - sq(p[2]) / (v[1] * v[1]) + (v[2] == 1 ? -1.0 : 1.0);
}

std::string check_hyperboloid(Values v) {
    if (std::string e = all_positive(v, {"a", "c"}); !e.empty()) return e;
    if (v[2] != 1 && v[2] != 2) return "sheets must be 1 or 2, but it is " + format_number(v[2]);
    return "";
}

Expr torus(const ExprVector& p, Values v) {
    const double big = v[0];
    const double small = v[1];
    const Expr rho2 = sq(p[0]) + sq(p[1]);
    return sq(rho2 + sq(p[2]) + (big * big - small * small)) - 4 * big * big * rho2;
}

Expr steiner(const ExprVector& p, Values) {
    const Expr &x = p[0], &y = p[1], &z = p[2];
    return sq(x) * sq(y) + sq(y) * sq(z) + sq(z) * sq(x) - x * y * z;
}

// (x² + y² + z² − μ²)² − λ p q r s over the four planes of a tetrahedron,
// λ = (3μ² − 1)/(3 − μ²).
Expr kummer(const ExprVector& p, Values v) {
    const double mu2 = v[0];
    const double lambda = (3 * mu2 - 1) / (3 - mu2);
    const Expr &x = p[0], &y = p[1], &z = p[2];
    const double r2 = std::numbers::sqrt2;
    const Expr planes = (1.0 - z - r2 * x) * (1.0 - z + r2 * x) * (1.0 + z + r2 * y) * (1.0 + z - r2 * y);
    return sq(sq(x) + sq(y) + sq(z) - mu2) - lambda * planes;
}

std::string check_kummer(Values v) {
    if (!(v[0] > 1.0 / 3.0 && v[0] < 3))
        return "mu2 must be between 1/3 and 3 (16 real nodes), but it is " + format_number(v[0]);
    return "";
}

Expr clebsch(const ExprVector& p, Values) {
    const Expr &x = p[0], &y = p[1], &z = p[2];
    const Expr cubes = powi(x, 3) + powi(y, 3) + powi(z, 3);
    const Expr mixed = sq(x) * y + sq(x) * z + sq(y) * x + sq(y) * z + sq(z) * x + sq(z) * y;
    return 81 * cubes - 189 * mixed + 54 * x * y * z + 126 * (x * y + x * z + y * z) -
           9 * (sq(x) + sq(y) + sq(z)) - 9 * (x + y + z) + 1.0;
}

// Negated from the published form, so that f > 0 at the origin and on nearly
// all of the sphere of radius 1.8: clipped by a ball, the spikes are the inside.
Expr barth_sextic(const ExprVector& p, Values) {
    const double phi = std::numbers::phi;
    const double phi2 = phi * phi;
    const Expr x2 = sq(p[0]), y2 = sq(p[1]), z2 = sq(p[2]);
    return (1 + 2 * phi) * sq(x2 + y2 + z2 - 1.0) - 4 * (phi2 * x2 - y2) * (phi2 * y2 - z2) * (phi2 * z2 - x2);
}

// T₈(t) = 128t⁸ − 256t⁶ + 160t⁴ − 32t² + 1, the Chebyshev polynomial of degree 8.
Expr chebyshev_t8(const Expr& t) {
    const Expr t2 = sq(t);
    return (((128 * t2 - 256) * t2 + 160) * t2 - 32) * t2 + 1.0;
}

// The + 1 lets critical values −1, −1, +1 of T₈ cancel: 3·3·4·4 = 144 real nodes.
Expr chmutov_octic(const ExprVector& p, Values) {
    return chebyshev_t8(p[0]) + chebyshev_t8(p[1]) + chebyshev_t8(p[2]) + 1.0;
}

// Endraß's X⁺ with w = 1, Q² − 64(x²−1)(y²−1)((x+y)²−2)((x−y)²−2) (negated like
// the Barth sextic, so a ball clip of radius 1.8 is nearly all outside), with
// Q = −4(1+√2)(x²+y²)² + (8(2+√2)z² + 2(2+7√2))(x²+y²) − 16z⁴ + 8(1−2√2)z² − (1+12√2).
Expr endrass_octic(const ExprVector& p, Values) {
    const Expr &x = p[0], &y = p[1], &z = p[2];
    const double s = std::numbers::sqrt2;
    const Expr rho2 = sq(x) + sq(y);
    const Expr z2 = sq(z);
    const Expr lhs = 64 * (sq(x) - 1.0) * (sq(y) - 1.0) * (sq(x + y) - 2.0) * (sq(x - y) - 2.0);
    const Expr q = -4 * (1 + s) * sq(rho2) + (8 * (2 + s) * z2 + 2 * (2 + 7 * s)) * rho2 - 16 * sq(z2) +
                   8 * (1 - 2 * s) * z2 - (1 + 12 * s);
    return sq(q) - lhs;
}

Expr tangle_cube(const ExprVector& p, Values) {
    const auto term = [](const Expr& t) { return powi(t, 4) - 5 * sq(t); };
    return term(p[0]) + term(p[1]) + term(p[2]) + 11.8;
}

Expr piriform(const ExprVector& p, Values) { return powi(p[0], 4) - powi(p[0], 3) + sq(p[1]) + sq(p[2]); }

Expr lemniscate_of_gerono(const ExprVector& p, Values) { return powi(p[0], 4) - sq(p[0]) + sq(p[1]) + sq(p[2]); }

Expr monkey_saddle(const ExprVector& p, Values) { return p[2] - powi(p[0], 3) + 3 * p[0] * sq(p[1]); }

Expr monomial(const ExprVector& p, Values v) {
    return v[0] * powi(p[0], static_cast<int>(v[1])) * powi(p[1], static_cast<int>(v[2])) *
           powi(p[2], static_cast<int>(v[3]));
}

constexpr double max_monomial_exponent = 64;

std::string check_monomial(Values v) {
    const char* const names[] = {"i", "j", "k"};
    for (int i = 0; i < 3; ++i) {
        const double n = v[static_cast<std::size_t>(i) + 1];
        if (!(n >= 0 && n <= max_monomial_exponent && n == std::floor(n)))
            return std::string(names[i]) + " must be an integer from 0 to 64, but it is " + format_number(n);
    }
    return "";
}

const std::vector<AlgebraicSurface>& table() {
    static const std::vector<AlgebraicSurface> surfaces{
        {"ellipsoid", {{"a", 1}, {"b", 1}, {"c", 1}}, "x^2/a^2 + y^2/b^2 + z^2/c^2 - 1", 2, ellipsoid,
         [](Values v) { return all_positive(v, {"a", "b", "c"}); }},
        {"cylinder", {{"r", 1}}, "x^2 + y^2 - r^2", 2, cylinder, [](Values v) { return all_positive(v, {"r"}); }},
        {"cone", {{"k", 1}}, "x^2 + y^2 - k^2*z^2", 2, cone, [](Values v) { return all_positive(v, {"k"}); }},
        {"paraboloid", {{"k", 1}}, "x^2 + y^2 - k*z", 2, paraboloid,
         [](Values v) { return all_positive(v, {"k"}); }},
        {"hyperboloid", {{"a", 1}, {"c", 1}, {"sheets", 1}},
         "(x^2 + y^2)/a^2 - z^2/c^2 - 1 (sheets 1) or + 1 (sheets 2)", 2, hyperboloid, check_hyperboloid},
        {"torus", {{"R", 1}, {"r", 0.35}}, "(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)", 4, torus,
         [](Values v) { return all_positive(v, {"R", "r"}); }},
        {"steiner", {}, "x^2*y^2 + y^2*z^2 + z^2*x^2 - x*y*z", 4, steiner, no_check},
        {"kummer", {{"mu2", 1.69}},
         "(x^2 + y^2 + z^2 - mu2)^2 - lambda*p*q*r*s, lambda = (3*mu2 - 1)/(3 - mu2), "
         "p, q = 1 - z -+ sqrt(2)*x, r, s = 1 + z +- sqrt(2)*y",
         4, kummer, check_kummer},
        {"clebsch", {},
         "81*(x^3 + y^3 + z^3) - 189*(x^2*y + x^2*z + y^2*x + y^2*z + z^2*x + z^2*y) + 54*x*y*z"
         " + 126*(x*y + x*z + y*z) - 9*(x^2 + y^2 + z^2) - 9*(x + y + z) + 1",
         3, clebsch, no_check},
        {"barth_sextic", {},
         "(1 + 2*phi)*(x^2 + y^2 + z^2 - 1)^2 - 4*(phi^2*x^2 - y^2)*(phi^2*y^2 - z^2)*(phi^2*z^2 - x^2), "
         "phi = (1 + sqrt(5))/2",
         6, barth_sextic, no_check},
        {"chmutov_octic", {}, "T8(x) + T8(y) + T8(z) + 1, T8(t) = 128*t^8 - 256*t^6 + 160*t^4 - 32*t^2 + 1", 8,
         chmutov_octic, no_check},
        {"endrass_octic", {},
         "Q^2 - 64*(x^2 - 1)*(y^2 - 1)*((x + y)^2 - 2)*((x - y)^2 - 2), Q = -4*(1 + sqrt(2))*(x^2 + y^2)^2"
         " + (8*(2 + sqrt(2))*z^2 + 2*(2 + 7*sqrt(2)))*(x^2 + y^2) - 16*z^4 + 8*(1 - 2*sqrt(2))*z^2"
         " - (1 + 12*sqrt(2))",
         8, endrass_octic, no_check},
        {"tangle_cube", {}, "x^4 - 5*x^2 + y^4 - 5*y^2 + z^4 - 5*z^2 + 11.8", 4, tangle_cube, no_check},
        {"piriform", {}, "x^4 - x^3 + y^2 + z^2", 4, piriform, no_check},
        {"lemniscate_of_gerono", {}, "x^4 - x^2 + y^2 + z^2", 4, lemniscate_of_gerono, no_check},
        {"monkey_saddle", {}, "z - x^3 + 3*x*y^2", 3, monkey_saddle, no_check},
        {"monomial", {{"c", 1}, {"i", 0}, {"j", 0}, {"k", 0}}, "c*x^i*y^j*z^k", -1, monomial, check_monomial},
    };
    return surfaces;
}

}  // namespace

std::span<const AlgebraicSurface> algebraic_surfaces() { return table(); }

const AlgebraicSurface* find_algebraic_surface(std::string_view name) {
    const auto& all = table();
    const auto it = std::ranges::find(all, name, &AlgebraicSurface::name);
    return it == all.end() ? nullptr : &*it;
}

std::string signature(const AlgebraicSurface& surface) {
    std::string text = std::string(surface.name) + "(";
    for (const AlgebraicParameter& p : surface.parameters)
        text += std::string(p.name) + " = " + format_number(p.default_value) + ", ";
    return text + "[point])";
}

std::vector<double> with_defaults(const AlgebraicSurface& surface, std::span<const double> values) {
    std::vector<double> all;
    for (std::size_t i = 0; i < surface.parameters.size(); ++i)
        all.push_back(i < values.size() ? values[i] : surface.parameters[i].default_value);
    return all;
}

Expr build_algebraic_surface(const AlgebraicSurface& surface, std::span<const double> values, const ExprVector& p) {
    return surface.build(p, with_defaults(surface, values));
}

}  // namespace zeroset
