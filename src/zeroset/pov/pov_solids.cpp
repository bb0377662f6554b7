// POV-Ray's solids (sphere, box, plane, cylinder, cone, torus) and
// polynomial surfaces (quadric, cubic, quartic, poly, polynomial) as
// implicit objects, each a polynomial the polynomial method traces exactly
// (the box's slabs aside).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "zeroset/pov/pov_object_parts.hpp"

namespace zeroset::pov {

namespace {

/// Where an unbounded surface (a plane's tilted cousins, an open quadric) is
/// looked for when the scene gives no bounded_by or clipped_by: POV-Ray
/// draws it without end, zeroset within this box.
constexpr double unbounded_extent = 1e4;

/// The number of terms of a polynomial of degree n in three variables.
std::size_t term_count(int n) { return static_cast<std::size_t>((n + 1) * (n + 2) * (n + 3) / 6); }

/// A term c·xⁱyʲzᵏ of a polynomial.
struct Monomial {
    std::array<int, 3> power;
    double coefficient;
};

/// A sparse multivariate Horner form of the sum of `terms` (distinct powers,
/// none with a zero coefficient): the variable found in the most terms is
/// factored out of them, at its lowest power there, and both parts are
/// written so in turn. No product by a zero coefficient is made — a dense
/// Horner form's made POV-Ray's mostly sparse polynomials 3× slower to form
/// along a ray — and fewer products than term by term: the torus's ten
/// terms, (x² + 2y² + 2z² − 104)·x² + (y² + 2z² + 56)·y² + (z² − 104)·z² +
/// 784, take 16 % fewer instructions to render than their sum. The
/// coefficients are POV-Ray's own, untouched: the same polynomial exactly.
Expr sparse_horner(std::vector<Monomial> terms, const ExprPoint& p) {
    if (terms.empty()) return Expr(0.0);
    int variable = -1;
    std::size_t most = 0;
    for (int v = 0; v < 3; ++v) {
        const auto count = static_cast<std::size_t>(
            std::count_if(terms.begin(), terms.end(), [v](const Monomial& t) { return t.power[static_cast<std::size_t>(v)] > 0; }));
        if (count > most) {
            most = count;
            variable = v;
        }
    }
    if (variable < 0) {  // the constant term (one at most: the powers are distinct)
        double constant = 0.0;
        for (const Monomial& t : terms) constant += t.coefficient;
        return Expr(constant);
    }
    const auto v = static_cast<std::size_t>(variable);
    const auto split = std::stable_partition(terms.begin(), terms.end(), [v](const Monomial& t) { return t.power[v] > 0; });
    std::vector<Monomial> with(terms.begin(), split), without(split, terms.end());
    int lowest = with.front().power[v];
    for (const Monomial& t : with) lowest = std::min(lowest, t.power[v]);
    for (Monomial& t : with) t.power[v] -= lowest;
    const Expr factored = sparse_horner(std::move(with), p) * powi(p[variable], lowest);
    return without.empty() ? factored : factored + sparse_horner(std::move(without), p);
}

/// The polynomial of degree n whose coefficients `c` are in POV-Ray's order
/// of a poly's terms: xⁱyʲzᵏ by descending i, then j, then k.
Expr poly_expression(int n, const std::vector<double>& c) {
    std::vector<Monomial> terms;
    std::size_t index = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            for (int k = n - i - j; k >= 0; --k) {
                const double a = c[index++];
                if (a != 0.0) terms.push_back({{i, j, k}, a});
            }
    return sparse_horner(std::move(terms), coordinates());
}

std::shared_ptr<PovObject> leaf(const PovToken& keyword, const std::string& where, Expr f, Bounds bounds) {
    auto node = object_node(keyword, where);
    node->object.surface = std::move(f);
    node->object.bounds = std::move(bounds);
    return wrap(keyword, std::move(node));
}

Bounds grown_box(const Vec3d& lo, const Vec3d& hi) {
    const Vec3d margin = (hi - lo) * 0.01 + Vec3d{1e-9, 1e-9, 1e-9};
    return Bounds::make_box({lo - margin, hi + margin});
}

}  // namespace

std::shared_ptr<PovObject> PovParser::sphere(const PovToken& keyword, ObjectBuilder& b) {
    const Vec3d c = vector3("the sphere's center");
    accept_symbol(",");  // POV-Ray lets it be left out
    const double r = number("the sphere's radius");
    if (!(r > 0.0)) fail(keyword, "the sphere's radius must be positive");
    object_modifiers(b);
    const Expr f = ball(coordinates(), c, r);
    const Vec3d h{r, r, r};
    auto o = leaf(keyword, located(keyword), f, grown_box(c - h, c + h));
    o->shape = Bounds::make_sphere(c, r);
    return o;
}

std::shared_ptr<PovObject> PovParser::box(const PovToken& keyword, ObjectBuilder& b) {
    const Vec3d a = vector3("the box's first corner");
    accept_symbol(",");  // POV-Ray lets it be left out
    const Vec3d z = vector3("the box's second corner");
    object_modifiers(b);
    const Vec3d lo = min(a, z), hi = max(a, z);
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) fail(keyword, "the box is flat (its corners share a coordinate)");
    const Vec3d c = (lo + hi) * 0.5, h = (hi - lo) * 0.5;
    const Expr f = slabs(coordinates(), c, h);
    auto o = leaf(keyword, located(keyword), f, grown_box(lo, hi));
    o->shape = Bounds::make_box({lo, hi});
    return o;
}

std::shared_ptr<PovObject> PovParser::plane(const PovToken& keyword, ObjectBuilder& b) {
    const Vec3d n = vector3("the plane's normal");
    accept_symbol(",");  // POV-Ray lets it be left out
    const double d = number("the plane's distance");
    object_modifiers(b);
    if (!(length(n) > 0.0)) fail(keyword, "the plane's normal must not be 0");
    const Vec3d u = normalize(n);
    const ExprPoint p = coordinates();
    const Expr f = Expr(u.x) * p.x + Expr(u.y) * p.y + Expr(u.z) * p.z - Expr(d);
    return leaf(keyword, located(keyword), f, Bounds::none());
}

std::shared_ptr<PovObject> PovParser::cylinder_or_cone(const PovToken& keyword, ObjectBuilder& b) {
    const bool cone = keyword.text == "cone";
    const Vec3d a = vector3("the base point");
    accept_symbol(",");  // POV-Ray lets it be left out
    double ra = 0.0;
    if (cone) {
        ra = number("the base radius");
        accept_symbol(",");  // POV-Ray lets it be left out
    }
    const Vec3d z = vector3("the cap point");
    accept_symbol(",");  // POV-Ray lets it be left out
    const double rz = number(cone ? "the cap radius" : "the radius");
    if (!cone) ra = rz;
    bool open = false;
    object_modifiers(b, [&](const PovToken& t) {
        if (!t.is_name("open")) return false;
        next();
        open = true;
        return true;
    });
    const double height = length(z - a);
    if (!(height > 0.0)) fail(keyword, "the " + keyword.text + "'s ends must differ");
    if (ra < 0.0 || rz < 0.0 || (ra == 0.0 && rz == 0.0)) fail(keyword, "the " + keyword.text + "'s radii must be positive");
    // In a frame with the axis along z from 0 to the height: x² + y² − r(z)²,
    // a quadric the polynomial method traces exactly; its caps are where the
    // bounds cut it, and an open one is left open there.
    const Vec3d e = (z - a) / height;
    const Vec3d helper = std::abs(e.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d u = normalize(cross(helper, e)), v = cross(e, u);
    Mat4 frame = Mat4::identity();
    for (std::size_t row = 0; row < 3; ++row) {
        frame.m[row][0] = u[static_cast<int>(row)];
        frame.m[row][1] = v[static_cast<int>(row)];
        frame.m[row][2] = e[static_cast<int>(row)];
        frame.m[row][3] = a[static_cast<int>(row)];
    }
    const ExprPoint p = coordinates();
    const Expr radius = ra == rz ? Expr(ra) : Expr(ra) + p.z * Expr((rz - ra) / height);
    const Expr f = square(p.x) + square(p.y) - square(radius);
    const double r = std::max(ra, rz) * 1.01;
    auto node = object_node(keyword, located(keyword));
    node->object.surface = f;
    node->object.bounds = Bounds::make_box({{-r, -r, 0.0}, {r, r, height}});
    node->object.cut_by_bounds = true;
    node->object.open = open;
    node->transform = frame;
    return wrap(keyword, std::move(node));
}

std::shared_ptr<PovObject> PovParser::torus(const PovToken& keyword, ObjectBuilder& b) {
    const double big = number("the torus's major radius");
    accept_symbol(",");  // POV-Ray lets it be left out
    const double small = number("the torus's minor radius");
    object_modifiers(b);
    if (!(big > 0.0 && small > 0.0)) fail(keyword, "the torus's radii must be positive");
    // (x² + y² + z² + R² − r²)² − 4R²(x² + z²), around y: a quartic, traced exactly.
    const ExprPoint p = coordinates();
    const Expr s = square(p.x) + square(p.y) + square(p.z) + Expr(big * big - small * small);
    const Expr f = square(s) - Expr(4.0 * big * big) * (square(p.x) + square(p.z));
    const double o = big + small;
    return leaf(keyword, located(keyword), f, grown_box({-o, -small, -o}, {o, small, o}));
}

std::shared_ptr<PovObject> PovParser::polynomial(const PovToken& keyword, ObjectBuilder& b) {
    const std::string& w = keyword.text;
    int degree = 0;
    std::vector<double> c;
    const auto coefficients = [&](std::size_t n) {
        expect_symbol("<", "before the coefficients");
        for (std::size_t i = 0; i < n; ++i) {
            // POV-Ray lets a comma between coefficients be left out (a row's end, say).
            if (i > 0 && !accept_symbol(",") && peek().is_symbol(">"))
                fail_expected("more coefficients (" + std::to_string(n) + " of them)");
            const PovToken at = peek();
            const PovValue v = conditional_expression(true);  // in a vector: '>' closes it
            if (!v.is_number()) fail(at, "a coefficient must be a number");
            c.push_back(v.v[0]);
        }
        expect_symbol(">", "after the " + std::to_string(n) + " coefficients");
    };
    if (w == "quadric") {
        degree = 2;
        // <A, B, C>, <D, E, F>, <G, H, I>, J: Ax² + By² + Cz² + Dxy + Exz + Fyz + Gx + Hy + Iz + J.
        std::array<double, 10> q{};
        for (std::size_t v = 0; v < 3; ++v) {
            const Vec3d t = vector3("the quadric's coefficients");
            q[3 * v] = t.x, q[3 * v + 1] = t.y, q[3 * v + 2] = t.z;
            accept_symbol(",");  // POV-Ray lets it be left out
        }
        q[9] = number("the quadric's constant");
        // In POV-Ray's poly order: x², xy, xz, x, y², yz, y, z², z, 1.
        c = {q[0], q[3], q[4], q[6], q[1], q[5], q[7], q[2], q[8], q[9]};
    } else if (w == "cubic" || w == "quartic") {
        degree = w == "cubic" ? 3 : 4;
        coefficients(term_count(degree));
    } else if (w == "poly") {
        const double n = number("the poly's order");
        if (!(n >= 2 && n <= 32 && n == std::floor(n))) fail(keyword, "the poly's order must be a whole number from 2 to 32");
        degree = static_cast<int>(n);
        accept_symbol(",");  // POV-Ray lets it be left out
        coefficients(term_count(degree));
    } else {  // polynomial { order, xyz(i, j, k): c, … }
        const double n = number("the polynomial's order");
        if (!(n >= 1 && n <= 32 && n == std::floor(n))) fail(keyword, "the polynomial's order must be a whole number from 1 to 32");
        degree = static_cast<int>(n);
        c.assign(term_count(degree), 0.0);
        while (accept_symbol(",")) {
            const PovToken at = peek();
            if (!accept_name("xyz")) fail_expected("xyz(i, j, k): coefficient");
            expect_symbol("(", "after xyz");
            const double i = number("x's power");
            accept_symbol(",");  // POV-Ray lets it be left out
            const double j = number("y's power");
            accept_symbol(",");  // POV-Ray lets it be left out
            const double k = number("z's power");
            expect_symbol(")", "after xyz's powers");
            expect_symbol(":", "after xyz(…)");
            const double value = number("the coefficient");
            if (!(i >= 0 && j >= 0 && k >= 0 && i + j + k <= degree && i == std::floor(i) && j == std::floor(j) && k == std::floor(k)))
                fail(at, "xyz's powers must be whole numbers adding up to at most the order");
            // Its place in POV-Ray's order.
            std::size_t index = 0;
            for (int a = degree; a >= 0; --a)
                for (int bb = degree - a; bb >= 0; --bb)
                    for (int cc = degree - a - bb; cc >= 0; --cc) {
                        if (a == static_cast<int>(i) && bb == static_cast<int>(j) && cc == static_cast<int>(k)) c[index] = value;
                        ++index;
                    }
        }
    }
    object_modifiers(b);
    auto node = object_node(keyword, located(keyword));
    Object& o = node->object;
    o.surface = poly_expression(degree, c);
    constexpr double e = unbounded_extent;
    o.bounds = Bounds::make_box({{-e, -e, -e}, {e, e, e}});
    if (o.surface.is_constant_valued()) fail(keyword, "the " + w + "'s coefficients are all 0 but the constant");
    // A polynomial surface is a sheet, as POV-Ray draws it, clipped by
    // clipped_by in finish_object; a bounded_by sphere or box is its gate.
    o.open = true;
    if (b.bounded_by && !b.bounded_by->object->inverse) {
        if (const auto region =
                clip_region(*b.bounded_by->object, b.bounded_by->to_local, b.bounded_by->where, RegionUse::Gate)) {
            o.gate = *region;
            b.bounded_by.reset();
        }
    }
    return wrap(keyword, std::move(node));
}

}  // namespace zeroset::pov
