// POV-Ray's objects as the scene's tree: the solids (sphere, box, plane,
// cylinder, cone, torus) and polynomial surfaces (quadric, cubic, quartic,
// poly, polynomial) as implicit objects, blobs as the blob primitive with
// POV-Ray's kernel, isosurfaces as objects of their function, CSG as
// groups, intersections and differences, and the modifiers every object
// takes (transforms, textures, inverse, bounded_by, clipped_by).
#include <algorithm>
#include <cmath>
#include <functional>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/substitute.hpp"
#include "zeroset/pov/pov_parser.hpp"
#include "zeroset/trace/sweep_path.hpp"

namespace zeroset::pov {

namespace {

constexpr std::array<std::string_view, 14> supported_objects{
    "sphere", "box",     "plane", "cylinder",   "cone", "torus",      "quadric",
    "cubic",  "quartic", "poly",  "polynomial", "blob", "isosurface", "sphere_sweep"};
constexpr std::array<std::string_view, 5> csg_objects{"union", "merge", "intersection", "difference", "object"};
constexpr std::array<std::string_view, 17> unsupported_objects{
    "lathe", "sor",      "prism",       "superellipsoid", "height_field", "mesh",    "mesh2",  "text",  "julia_fractal",
    "bicubic_patch", "disc", "triangle", "smooth_triangle", "polygon", "parametric", "ovus", "lemon"};

template <std::size_t N>
bool among(const std::array<std::string_view, N>& words, std::string_view w) {
    return std::find(words.begin(), words.end(), w) != words.end();
}

/// Where an unbounded surface (a plane's tilted cousins, an open quadric) is
/// looked for when the scene gives no bounded_by or clipped_by: POV-Ray
/// draws it without end, zeroset within this box.
constexpr double unbounded_extent = 1e4;

/// The solid of a ball, |p − c|² − r², a quadric.
Expr ball(const ExprPoint& p, const Vec3d& c, double r) {
    return square(p.x - Expr(c.x)) + square(p.y - Expr(c.y)) + square(p.z - Expr(c.z)) - Expr(r * r);
}

/// The solid of an axis-aligned box of centre c and half-size h: the max of its slabs.
Expr slabs(const ExprPoint& p, const Vec3d& c, const Vec3d& h) {
    return max(max(abs(p.x - Expr(c.x)) - Expr(h.x), abs(p.y - Expr(c.y)) - Expr(h.y)), abs(p.z - Expr(c.z)) - Expr(h.z));
}

/// The linear part's scale when it is a rotation times a uniform scale.
std::optional<double> similarity_scale(const Mat4& m) {
    const Vec3d a = m.transform_vector({1, 0, 0}), b = m.transform_vector({0, 1, 0}), c = m.transform_vector({0, 0, 1});
    const double s = length(a);
    const double tolerance = 1e-9 * s;
    if (std::abs(length(b) - s) > tolerance || std::abs(length(c) - s) > tolerance) return std::nullopt;
    if (std::abs(dot(a, b)) > tolerance * s || std::abs(dot(a, c)) > tolerance * s || std::abs(dot(b, c)) > tolerance * s)
        return std::nullopt;
    return s;
}

/// Whether the linear part only scales the axes (a diagonal matrix).
bool axis_aligned(const Mat4& m) {
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c)
            if (r != c && m.m[r][c] != 0.0) return false;
    return true;
}

/// The number of terms of a polynomial of degree n in three variables.
std::size_t term_count(int n) { return static_cast<std::size_t>((n + 1) * (n + 2) * (n + 3) / 6); }

/// POV-Ray's order of a poly's terms: xⁱyʲzᵏ by descending i, then j, then
/// k. Summed term by term, the zero ones left out: POV-Ray's polynomials are
/// mostly sparse, and a Horner form's products by zero coefficients made
/// the ray polynomial 3× slower to form (and its rounding bound wider).
Expr poly_expression(int n, const std::vector<double>& c) {
    const ExprPoint p = coordinates();
    Expr sum(0.0);
    std::size_t index = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            for (int k = n - i - j; k >= 0; --k) {
                const double a = c[index++];
                if (a == 0.0) continue;
                Expr term(a);
                if (i > 0) term = term * powi(p.x, i);
                if (j > 0) term = term * powi(p.y, j);
                if (k > 0) term = term * powi(p.z, k);
                sum = sum + term;
            }
    return sum;
}

}  // namespace

struct PovParser::ObjectBuilder {
    PovToken keyword;
    Mat4 transform = Mat4::identity();  // after the object's own parameters
    std::optional<PovTexture> texture;
    bool inverse = false;
    /// A bounded_by or clipped_by object, and the map from its space into
    /// the object's own (the transforms before it do not move it).
    struct Limit {
        std::shared_ptr<const PovObject> object;
        Mat4 to_local;
        PovToken where;
    };
    std::optional<Limit> bounded_by;
    std::vector<Limit> clipped_by;  // clipped by all of them
};

bool PovParser::starts_object(const PovToken& t) const {
    if (t.kind != PovTokenKind::Name) return false;
    return among(supported_objects, t.text) || among(csg_objects, t.text) || among(unsupported_objects, t.text);
}

bool PovParser::starts_optional_switch() {
    const PovToken& t = peek();
    if (t.kind == PovTokenKind::Number) return true;
    if (t.kind != PovTokenKind::Name) return false;
    static constexpr std::array<std::string_view, 6> words{"on", "off", "true", "false", "yes", "no"};
    return among(words, t.text) || (lookup(t.text) && lookup(t.text)->is_number());
}

bool PovParser::is_transform(const PovToken& t) const {
    return t.kind == PovTokenKind::Name &&
           (t.text == "translate" || t.text == "rotate" || t.text == "scale" || t.text == "matrix" || t.text == "transform");
}

Mat4 PovParser::transform_statement(const PovToken& keyword) {
    const Nesting nesting(*this);
    const std::string& w = keyword.text;
    if (w == "translate") return Mat4::translate(vector3("translate"));
    if (w == "rotate") return Mat4::rotate_xyz_degrees(vector3("rotate"));
    if (w == "scale") {
        const Vec3d s = vector3("scale");
        if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) fail(keyword, "scale by 0 flattens the object");
        return Mat4::scale(s);
    }
    if (w == "matrix") {
        expect_symbol("<", "after matrix");
        std::array<double, 12> v{};
        for (std::size_t i = 0; i < 12; ++i) {
            if (i > 0) accept_symbol(",");  // POV-Ray lets it be left out
            const PovToken at = peek();
            const PovValue entry = conditional_expression(true);  // in a vector: '>' closes it
            if (!entry.is_number()) fail(at, "a matrix entry must be a number");
            v[i] = entry.v[0];
        }
        expect_symbol(">", "after the matrix's 12 numbers");
        Mat4 m = Mat4::identity();
        for (std::size_t row = 0; row < 3; ++row)
            for (std::size_t col = 0; col < 4; ++col) m.m[row][col] = v[col * 3 + row];  // POV-Ray's rows are columns here
        if (!m.inverse()) fail(keyword, "the matrix is singular");
        return m;
    }
    // transform Name, or transform { … } with transforms, names and `inverse`.
    if (peek().kind == PovTokenKind::Name && !peek().is_symbol("{")) {
        const PovToken name = next();
        const PovValue* v = use(name.text);
        if (!v || v->kind != PovValue::Kind::Transform) fail(name, "'" + name.text + "' is not a declared transform");
        return v->transform;
    }
    expect_symbol("{", "after transform");
    Mat4 m = Mat4::identity();
    bool inverse = false;  // wherever it is written, `inverse` inverts the whole block
    while (!accept_symbol("}")) {
        const PovToken t = next();
        if (t.is_name("inverse")) {
            inverse = !inverse;
        } else if (is_transform(t)) {
            m = transform_statement(t) * m;
        } else if (const PovValue* v = t.kind == PovTokenKind::Name ? use(t.text) : nullptr;
                   v && v->kind == PovValue::Kind::Transform) {
            m = v->transform * m;
        } else {
            fail(t, "expected a transform, inverse or '}' in the transform block but found " + describe(t));
        }
    }
    if (inverse) {
        const auto back = m.inverse();
        if (!back) fail(keyword, "the transform cannot be inverted (it flattens space)");
        return *back;
    }
    return m;
}

std::shared_ptr<const PovObject> PovParser::object_statement() {
    const Nesting nesting(*this);
    const PovToken k = next();
    if (++object_count_ > 1'000'000) fail(k, "the scene makes more than 1 000 000 objects");
    if (among(unsupported_objects, k.text))
        fail(k, k.text + " is not supported: zeroset cannot reproduce its geometry (docs/povray.md lists what it reads)");
    ObjectBuilder b;
    b.keyword = k;
    expect_symbol("{", "after " + k.text);
    std::shared_ptr<PovObject> object;
    const std::string& w = k.text;
    if (w == "sphere") object = sphere(k, b);
    else if (w == "box") object = box(k, b);
    else if (w == "plane") object = plane(k, b);
    else if (w == "cylinder" || w == "cone") object = cylinder_or_cone(k, b);
    else if (w == "torus") object = torus(k, b);
    else if (w == "quadric" || w == "cubic" || w == "quartic" || w == "poly" || w == "polynomial") object = polynomial(k, b);
    else if (w == "blob") object = blob(k, b);
    else if (w == "isosurface") object = isosurface(k, b);
    else if (w == "sphere_sweep") object = sphere_sweep(k, b);
    else if (w == "object") object = object_reference(k, b);
    else object = csg(k, b);
    return finish_object(b, std::move(object));
}

void PovParser::object_modifiers(ObjectBuilder& b, const std::function<bool(const PovToken&)>& extra) {
    for (;;) {
        const PovToken t = peek();
        if (t.is_symbol("}")) {
            next();
            return;
        }
        if (t.kind == PovTokenKind::End) fail(b.keyword, "this " + b.keyword.text + " is not closed by '}'");
        if (extra && extra(t)) continue;
        if (t.kind != PovTokenKind::Name) fail_expected("an object modifier or '}'");
        const std::string& w = t.text;
        if (is_transform(t)) {
            next();
            b.transform = transform_statement(t) * b.transform;
        } else if (w == "texture" || w == "pigment" || w == "finish" || w == "normal" || w == "interior" || w == "material") {
            if (!b.texture) b.texture = PovTexture{};
            texture_item(*b.texture);
            if (w == "texture") layers(*b.texture);
        } else if (w == "inverse") {
            next();
            b.inverse = !b.inverse;
        } else if (w == "bounded_by" || w == "clipped_by") {
            next();
            expect_symbol("{", "after " + w);
            if (w == "bounded_by" && accept_name("clipped_by")) {
                if (b.clipped_by.empty()) fail(t, "bounded_by { clipped_by } needs a clipped_by before it");
                if (b.clipped_by.size() == 1) b.bounded_by = b.clipped_by.front();
                expect_symbol("}", "after bounded_by { clipped_by");
                continue;
            }
            if (w == "clipped_by" && accept_name("bounded_by")) {
                if (!b.bounded_by) fail(t, "clipped_by { bounded_by } needs a bounded_by before it");
                b.clipped_by.push_back(*b.bounded_by);
                expect_symbol("}", "after clipped_by { bounded_by");
                continue;
            }
            const Mat4 to_local = b.transform.inverse().value_or(Mat4::identity());
            std::vector<ObjectBuilder::Limit> limits{{object_statement(), to_local, t}};
            while (starts_object(peek())) limits.push_back({object_statement(), to_local, t});
            expect_symbol("}", "to close " + w);
            if (w == "clipped_by") {
                b.clipped_by.insert(b.clipped_by.end(), limits.begin(), limits.end());
            } else {
                if (limits.size() > 1) note(t, "bounded_by with several objects: only the first bounds the object");
                b.bounded_by = limits.front();
            }
        } else if (w == "hollow" || w == "sturm" || w == "double_illuminate" || w == "no_shadow" || w == "no_image" ||
                   w == "no_reflection" || w == "no_radiosity") {
            next();
            if (starts_optional_switch()) (void)number(w);  // an optional on/off
            if (w == "no_shadow" || w == "no_image" || w == "no_reflection")
                warn(t, w + " is not supported; the object is drawn, reflected and casts shadows as any other");
            else if (w == "sturm")
                note(t, "sturm is not needed: zeroset isolates every root of a polynomial surface");
        } else if (w == "photons" || w == "radiosity") {
            next();
            skip_block(t, w, nullptr);
        } else {
            fail(t, "unknown object modifier '" + w + "' in " + b.keyword.text);
        }
    }
}

namespace {

/// An object node of the scene's tree, named by its POV-Ray keyword.
std::shared_ptr<SceneNode> object_node(const PovToken& keyword, const std::string& where) {
    auto node = std::make_shared<SceneNode>();
    node->kind = SceneNode::Kind::Object;
    node->name = keyword.text;
    node->defined_at = where;
    return node;
}

std::shared_ptr<PovObject> wrap(const PovToken& keyword, SceneNodePtr node) {
    auto o = std::make_shared<PovObject>();
    o->node = std::move(node);
    o->kind = keyword.text;
    o->where = keyword.where;
    return o;
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

std::optional<Bounds> PovParser::clip_region(const PovObject& clip, const Mat4& to_local, const PovToken& at, bool exact) {
    if (!clip.shape) return std::nullopt;
    const Mat4 m = to_local * clip.node->transform;
    const Bounds& s = *clip.shape;
    if (s.kind == Bounds::Kind::Sphere) {
        if (const auto scale = similarity_scale(m)) return Bounds::make_sphere(m.transform_point(s.center), s.radius * *scale);
    } else if (axis_aligned(m)) {
        const Vec3d a = m.transform_point(s.box.lo), z = m.transform_point(s.box.hi);
        return Bounds::make_box({min(a, z), max(a, z)});
    }
    if (exact)
        warn(at, "clipping by a " + std::string(s.kind == Bounds::Kind::Sphere ? "sphere stretched unevenly" : "turned box") +
                     " is not supported; clipped by the box around it");
    return Bounds::make_box(m.transform_box(s.enclosing_box()));
}

std::optional<Expr> PovParser::solid_expression(const PovObject& clip, const Mat4& to_local) {
    const SceneNode& n = *clip.node;
    if (n.kind != SceneNode::Kind::Object || n.object.blob || n.object.sweep) return std::nullopt;
    const std::optional<Mat4> back = (to_local * n.transform).inverse();
    if (!back) return std::nullopt;
    // Its solid in its own space: f ≤ 0, within its bounds where they cut it
    // (an open surface clips by its solid too).
    const ExprPoint p = coordinates();
    Expr f = n.object.surface;
    const Bounds& b = n.object.bounds;
    if (n.object.cut_by_bounds && b.kind == Bounds::Kind::Box) f = max(f, slabs(p, b.box.center(), b.box.size() * 0.5));
    if (n.object.cut_by_bounds && b.kind == Bounds::Kind::Sphere) f = max(f, ball(p, b.center, b.radius));
    // … seen from the target's space: f(M⁻¹ x).
    ExprPoint q;
    for (int i = 0; i < 3; ++i) {
        const auto& row = back->m[static_cast<std::size_t>(i)];
        Expr sum(row[3]);
        for (int k = 0; k < 3; ++k) {  // the zero terms of a turn by right angles left out
            const double a = row[static_cast<std::size_t>(k)];
            if (a != 0.0) sum = sum + (a == 1.0 ? p[k] : Expr(a) * p[k]);
        }
        q[i] = sum;
    }
    const Expr g = substitute(f, q);
    return clip.inverse ? -g : g;
}

bool PovParser::clip_open(SceneNode& surface, const std::vector<std::pair<const PovObject*, Mat4>>& clips, const PovToken& at) {
    if (surface.kind != SceneNode::Kind::Object || surface.object.blob || surface.object.sweep ||
        surface.object.bounds.kind == Bounds::Kind::None)
        return false;
    const std::optional<Mat4> into_leaf = surface.transform.inverse();
    if (!into_leaf) return false;
    std::optional<Expr> clip = surface.object.clip;
    Box3 bounds = surface.object.bounds.enclosing_box();
    std::optional<Bounds> tighter;
    for (const auto& [object, to_local] : clips) {
        const Mat4 m = *into_leaf * to_local;
        const std::optional<Expr> g = solid_expression(*object, m);
        if (!g) return false;
        clip = clip ? max(*clip, *g) : *g;
        // A clipping sphere or box inside the bounds is tighter bounds.
        if (object->shape && !object->inverse)
            if (const auto region = clip_region(*object, m, at, false)) {  // bounds only: the clip itself is exact
                const Box3 r = region->enclosing_box();
                if (bounds.contains(r.lo) && bounds.contains(r.hi)) {
                    tighter = region;
                    bounds = r;
                }
            }
    }
    surface.object.open = true;
    surface.object.clip = clip;
    if (tighter) surface.object.bounds = *tighter;
    return true;
}

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
    // A polynomial surface is a sheet, as POV-Ray draws it; a bounded_by
    // sphere or box cuts it open, as the bounds of an open object (POV-Ray
    // clips by it too), and finish_object clips it by clipped_by.
    o.open = true;
    if (b.bounded_by && !b.bounded_by->object->inverse) {
        if (const auto region = clip_region(*b.bounded_by->object, b.bounded_by->to_local, b.bounded_by->where)) {
            o.bounds = *region;
            b.bounded_by.reset();
        }
    }
    return wrap(keyword, std::move(node));
}

std::shared_ptr<PovObject> PovParser::blob(const PovToken& keyword, ObjectBuilder& b) {
    double threshold = 1.0;
    std::vector<BlobComponent> components;
    const auto component_texture = [&](const PovToken& at) {
        warn(at, "a blob component's own texture is not supported; rendered with the blob's");
    };
    object_modifiers(b, [&](const PovToken& t) {
        if (t.is_name("threshold")) {
            next();
            threshold = number("the threshold");
            return true;
        }
        if (t.is_name("hierarchy")) {
            next();
            if (starts_optional_switch()) (void)number("hierarchy");
            return true;
        }
        if (t.is_name("component")) {  // the old syntax: strength, radius, center
            next();
            BlobComponent c;
            c.strength = number("the strength");
            accept_symbol(",");  // POV-Ray lets it be left out
            c.radius = number("the radius");
            accept_symbol(",");  // POV-Ray lets it be left out
            c.center = vector3("the center");
            components.push_back(c);
            return true;
        }
        if (!t.is_name("sphere") && !t.is_name("cylinder")) return false;
        next();
        expect_symbol("{", "after " + t.text);
        BlobComponent c;
        const bool cylinder = t.text == "cylinder";
        c.center = vector3(cylinder ? "the cylinder's first end" : "the center");
        accept_symbol(",");  // POV-Ray lets it be left out
        Vec3d end{};
        if (cylinder) {
            end = vector3("the cylinder's second end");
            accept_symbol(",");  // POV-Ray lets it be left out
        }
        c.radius = number("the radius");
        accept_symbol(",");
        accept_name("strength");
        c.strength = number("the strength");
        Mat4 shape = Mat4::identity();
        while (!accept_symbol("}")) {
            const PovToken m = peek();
            if (is_transform(m)) {
                next();
                shape = transform_statement(m) * shape;
            } else if (m.is_name("texture") || m.is_name("pigment") || m.is_name("finish") || m.is_name("normal")) {
                PovTexture ignored;
                texture_item(ignored);
                component_texture(m);
            } else {
                fail_expected("a transform, texture or '}' in the blob component");
            }
        }
        // POV-Ray moves a component about the origin: its center moves, and
        // the linear part shapes its kernel.
        if (cylinder) {  // moved, turned or scaled evenly: its ends move, its radius scales
            const double sx = length(shape.transform_vector({1, 0, 0})), sy = length(shape.transform_vector({0, 1, 0})),
                         sz = length(shape.transform_vector({0, 0, 1}));
            if (std::abs(sx - sy) > 1e-9 * sx || std::abs(sx - sz) > 1e-9 * sx || std::abs(shape.squareness() - 1.0) > 1e-9)
                fail(t, "a blob cylinder stretched unevenly is not supported (only moved, turned or scaled evenly)");
            c.end = shape.transform_point(end);
            c.center = shape.transform_point(c.center);
            c.radius *= sx;
        } else {
            c.center = shape.transform_point(c.center);
            Mat4 linear = shape;
            for (std::size_t row = 0; row < 3; ++row) linear.m[row][3] = 0.0;
            c.shape = linear;
        }
        components.push_back(c);
        return true;
    });
    if (components.empty()) fail(keyword, "the blob has no components");
    auto node = object_node(keyword, located(keyword));
    try {
        node->object.blob = std::make_shared<const BlobModel>(BlobKernel::PovRay, threshold, std::move(components));
    } catch (const std::invalid_argument& e) {
        fail(keyword, std::string("blob: ") + e.what());
    }
    const std::optional<Box3> reach = node->object.blob->solid_bounds(node->object.blob_tolerance);
    if (!reach) fail(keyword, "the blob has no component of positive strength: its field never reaches the threshold");
    node->object.bounds = Bounds::make_box(*reach);
    return wrap(keyword, std::move(node));
}

std::shared_ptr<PovObject> PovParser::isosurface(const PovToken& keyword, ObjectBuilder& b) {
    std::optional<Expr> f;
    double threshold = 0.0;
    Bounds container = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
    bool open = false;
    object_modifiers(b, [&](const PovToken& t) {
        const std::string& w = t.text;
        if (t.is_name("function")) {
            next();
            const auto fn = function_definition(t);
            f = apply(*fn, {var_x(), var_y(), var_z()}, t);
        } else if (t.is_name("threshold")) {
            next();
            threshold = number("the threshold");
        } else if (t.is_name("contained_by")) {
            next();
            expect_symbol("{", "after contained_by");
            const PovToken shape = expect_name("a box or sphere");
            expect_symbol("{", "after " + shape.text);
            if (shape.text == "box") {
                const Vec3d a = vector3("the box's first corner");
                accept_symbol(",");  // POV-Ray lets it be left out
                const Vec3d z = vector3("the box's second corner");
                container = Bounds::make_box({min(a, z), max(a, z)});
            } else if (shape.text == "sphere") {
                const Vec3d c = vector3("the sphere's center");
                accept_symbol(",");  // POV-Ray lets it be left out
                const double r = number("the sphere's radius");
                if (!(r > 0.0)) fail(shape, "the sphere's radius must be positive");
                container = Bounds::make_sphere(c, r);
            } else {
                fail(shape, "contained_by takes a box or a sphere");
            }
            expect_symbol("}", "to close the " + shape.text);
            expect_symbol("}", "to close contained_by");
        } else if (t.is_name("open")) {
            next();
            open = true;
        } else if (w == "max_gradient" || w == "accuracy" || w == "max_trace" || w == "evaluate") {
            next();
            (void)number(w);
            if (w == "evaluate") {
                accept_symbol(",");  // POV-Ray lets it be left out
                (void)number(w);
                accept_symbol(",");  // POV-Ray lets it be left out
                (void)number(w);
            }
            note(t, w + " is not needed: zeroset bounds the function's gradient itself and finds the first hit "
                        "without a step to choose");
        } else if (w == "all_intersections" || w == "polarity") {
            next();
            if (w == "polarity") (void)number(w);
            note(t, w + " is not needed");
        } else {
            return false;
        }
        return true;
    });
    if (!f) fail(keyword, "the isosurface has no function");
    if (f->is_constant_valued()) fail(keyword, "the isosurface's function does not depend on x, y or z");
    auto node = object_node(keyword, located(keyword));
    node->object.surface = *f - Expr(threshold);
    node->object.bounds = container;
    node->object.cut_by_bounds = true;  // POV-Ray draws the container's cut on purpose …
    node->object.open = open;           // … unless the isosurface is open
    return wrap(keyword, std::move(node));
}

std::shared_ptr<PovObject> PovParser::sphere_sweep(const PovToken& keyword, ObjectBuilder& b) {
    // sphere_sweep { linear_spline | cubic_spline | b_spline  N, <c>, r, …  [tolerance t] }:
    // the sweep primitive, whose splines are POV-Ray's (cubic_spline is
    // Catmull–Rom; both splines' first and last points only steer).
    const PovToken kind = expect_name("linear_spline, cubic_spline or b_spline");
    const SweepCurve curve = kind.text == "linear_spline"  ? SweepCurve::Linear
                             : kind.text == "cubic_spline" ? SweepCurve::CatmullRom
                             : kind.text == "b_spline"     ? SweepCurve::BSpline
                                                           : (fail(kind, "a sphere_sweep's spline is linear_spline, cubic_spline or b_spline"), SweepCurve::Linear);
    const double count = number("the number of spheres");
    if (!(count >= 2 && count <= 1'000'000 && count == std::floor(count))) fail(keyword, "the number of spheres must be a whole number from 2 to 1 000 000");
    std::vector<SweepPoint> points;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        accept_symbol(",");  // POV-Ray lets it be left out
        const Vec3d c = vector3("a sphere's center");
        accept_symbol(",");
        const double r = number("a sphere's radius");
        if (!(r >= 0.0)) fail(keyword, "a sphere's radius must not be negative");
        points.push_back({c, r});
    }
    object_modifiers(b, [&](const PovToken& t) {
        if (!t.is_name("tolerance")) return false;
        next();
        (void)number("the tolerance");
        note(t, "the sphere_sweep's tolerance is not needed: zeroset finds its spans by the roots of polynomials");
        return true;
    });
    if (curve != SweepCurve::Linear &&
        std::any_of(points.begin(), points.end(), [&](const SweepPoint& p) { return p.radius != points.front().radius; }))
        warn(keyword, "a spline sphere_sweep's radius goes linearly along each piece in zeroset, not with the spline; "
                      "the tube's thickness differs slightly between its points");
    auto node = object_node(keyword, located(keyword));
    try {
        node->object.sweep = std::make_shared<const std::vector<SweptSegment>>(sweep_segments(curve, points, false));
    } catch (const std::invalid_argument& e) {
        fail(keyword, std::string("sphere_sweep: ") + e.what());
    }
    Box3 box = empty_box();
    for (const SweptSegment& s : *node->object.sweep) box = united(box, s.bounds());
    node->object.bounds = Bounds::make_box(box);
    return wrap(keyword, std::move(node));
}

std::shared_ptr<PovObject> PovParser::object_reference(const PovToken& keyword, ObjectBuilder& b) {
    std::shared_ptr<const PovObject> inner;
    const PovToken t = peek();
    if (starts_object(t)) {
        inner = object_statement();
    } else {
        const PovToken name = expect_name("an object's name or an object");
        const PovValue* v = use(name.text);
        if (!v) fail(name, "unknown name '" + name.text + "'");
        if (v->kind != PovValue::Kind::Object) fail(name, "'" + name.text + "' is " + kind_name(v->kind) + ", not an object");
        inner = v->object;
    }
    object_modifiers(b);
    (void)keyword;
    return std::make_shared<PovObject>(*inner);
}

std::shared_ptr<PovObject> PovParser::csg(const PovToken& keyword, ObjectBuilder& b) {
    std::vector<std::shared_ptr<const PovObject>> children;
    object_modifiers(b, [&](const PovToken& t) {
        if (starts_object(t)) {
            children.push_back(object_statement());
            return true;
        }
        if (t.is_name("light_source")) {
            next();
            result_.scene.lights.push_back(light_block(t));
            warn(t, "a light inside an object is taken out of it: the object's transforms do not move it");
            return true;
        }
        if (t.is_name("split_union")) {
            next();
            (void)number("split_union");
            return true;
        }
        return false;
    });
    const std::string& w = keyword.text;
    if (children.empty()) fail(keyword, "the " + w + " has no objects");
    if (w == "merge") note(keyword, "merge is drawn as a union (the two are the same for opaque objects)");
    auto node = std::make_shared<SceneNode>();
    node->name = w;
    node->defined_at = located(keyword);
    auto o = std::make_shared<PovObject>();
    o->kind = w;
    o->where = keyword.where;
    o->node = node;
    if (w == "union" || w == "merge") {
        node->kind = SceneNode::Kind::Group;
        for (const auto& c : children) {
            if (c->inverse) fail(keyword, "an inverted object in a " + w + " is not supported (only in intersections and differences)");
            node->children.push_back(c->node);
        }
        return o;
    }
    // intersection { A B … }, difference { A B … } = intersection { A, inverse B, … }:
    // the solids kept and the solids taken away.
    std::vector<SceneNodePtr> kept, removed;
    std::vector<std::shared_ptr<const PovObject>> opaque, clear;
    for (std::size_t i = 0; i < children.size(); ++i) {
        const bool inverted = children[i]->inverse != (w == "difference" && i > 0);
        if (inverted) removed.push_back(children[i]->node);
        else (children[i]->clear ? clear : opaque).push_back(children[i]);
    }
    // An intersection with a clear sphere or box only clips: POV-Ray shows
    // the rest of the surface through it, open — as an open object in
    // bounds of that shape.
    if (opaque.size() == 1 && !clear.empty()) {
        auto clipped = std::make_shared<SceneNode>(*opaque.front()->node);
        std::vector<std::pair<const PovObject*, Mat4>> clips;
        for (const auto& c : clear) clips.emplace_back(c.get(), Mat4::identity());
        if (clip_open(*clipped, clips, keyword)) {
            clear.clear();
            auto o2 = std::make_shared<PovObject>(*opaque.front());
            o2->node = clipped;
            o2->shape.reset();
            opaque.front() = o2;
        }
    }
    if (!clear.empty())
        warn(keyword, "a clear object is drawn opaque here (zeroset draws transparency only as a clear sphere or box "
                      "clipping one surface)");
    for (const auto& c : opaque) kept.push_back(c->node);
    for (const auto& c : clear) kept.push_back(c->node);
    if (kept.empty()) fail(keyword, "an " + w + " of only inverted objects is not supported");
    SceneNodePtr base;
    if (kept.size() == 1) {
        base = kept.front();
    } else {
        auto meet = std::make_shared<SceneNode>();
        meet->kind = SceneNode::Kind::Intersection;
        meet->name = w;
        meet->defined_at = node->defined_at;
        meet->children = std::move(kept);
        base = meet;
    }
    if (removed.empty()) {  // the intersection, or its one member left
        o->node = base;
        return o;
    }
    node->kind = SceneNode::Kind::Difference;
    node->children.push_back(base);
    for (auto& r : removed) node->children.push_back(std::move(r));
    return o;
}

std::shared_ptr<PovObject> PovParser::finish_object(ObjectBuilder& b, std::shared_ptr<PovObject> object) {
    auto node = std::make_shared<SceneNode>(*object->node);
    if (!b.clipped_by.empty()) {
        object->shape.reset();
        std::vector<std::pair<const PovObject*, Mat4>> clips;
        for (const auto& c : b.clipped_by) clips.emplace_back(c.object.get(), c.to_local);
        if (!clip_open(*node, clips, b.clipped_by.front().where)) {
            // Not a surface of its own, or clipped by CSG: an intersection, closed.
            auto meet = std::make_shared<SceneNode>();
            meet->kind = SceneNode::Kind::Intersection;
            meet->name = node->name;
            meet->defined_at = node->defined_at;
            meet->children = {node};
            for (const auto& c : b.clipped_by) {
                if (c.object->inverse) fail(c.where, "clipping a group by an inverted object is not supported");
                auto clip_node = std::make_shared<SceneNode>(*c.object->node);
                clip_node->transform = c.to_local * clip_node->transform;
                meet->children.push_back(clip_node);
            }
            node = meet;
            warn(b.clipped_by.front().where, "clipped_by on a group leaves its cut open in POV-Ray; zeroset draws it "
                                             "closed (an intersection with the clipping objects)");
        }
    }
    if (b.bounded_by) {
        // On an open surface (a polynomial's sheet) POV-Ray's bounded_by cuts
        // it: there it is the object's bounds, when it fits in them.
        std::optional<Bounds> region;
        if (node->kind == SceneNode::Kind::Object && node->object.open && !b.bounded_by->object->inverse)
            if (const auto into_leaf = node->transform.inverse())
                region = clip_region(*b.bounded_by->object, *into_leaf * b.bounded_by->to_local, b.bounded_by->where);
        const Box3 now = node->kind == SceneNode::Kind::Object ? node->object.bounds.enclosing_box() : Box3{};
        if (region && now.contains(region->enclosing_box().lo) && now.contains(region->enclosing_box().hi))
            node->object.bounds = *region;
        else
            note(b.bounded_by->where, "bounded_by is not needed: zeroset bounds objects itself");
    }
    node->transform = b.transform * node->transform;
    if (!node->transform.is_finite()) fail(b.keyword, "the object's transforms overflow");
    if (node->kind == SceneNode::Kind::Object && !node->object.blob && !node->object.sweep && !node->object.fractal) {
        // Numbers too large for doubles: refused here, where the scene says them.
        const Bounds& bounds = node->object.bounds;
        const Vec3d c = bounds.kind == Bounds::Kind::None ? Vec3d{} : bounds.enclosing_box().center();
        const Tape tape(node->object.surface);
        Evaluator<double> f(tape);
        if (!std::isfinite(bounds.kind == Bounds::Kind::None ? 0.0 : bounds.enclosing_box().diagonal()) ||
            !std::isfinite(f(c.x, c.y, c.z)))
            fail(b.keyword, "the " + b.keyword.text + "'s numbers are too large for doubles (its function or bounds overflow)");
    }
    if (b.texture) {
        // A texture given again (object { Name pigment { … } }) goes over
        // the object's own, as in POV-Ray.
        PovTexture texture = object->texture.value_or(PovTexture{});
        texture.merge(*b.texture);
        node->material = material_of(texture, b.keyword);
        object->texture = texture;
        if (texture.color) {
            const auto& c = *texture.color;
            object->clear = c[4] >= 1.0 || (c[3] >= 1.0 && c[0] >= 1.0 && c[1] >= 1.0 && c[2] >= 1.0);
            if (!object->clear && (c[3] > 0.0 || c[4] > 0.0))
                warn(b.keyword, "transparency (filter, transmit) is not supported; rendered opaque");
        }
    }
    object->node = std::move(node);
    object->inverse = object->inverse != b.inverse;
    return object;
}

}  // namespace zeroset::pov
