// POV-Ray's objects as the scene's tree: which keyword starts which
// object, the modifiers every object takes (transforms, textures, inverse,
// bounded_by, clipped_by), clipping, object references and CSG as groups,
// intersections and differences. The objects themselves are read in
// pov_solids.cpp (the solids and polynomial surfaces) and
// pov_primitives.cpp (blobs, isosurfaces, sphere sweeps).
#include <algorithm>
#include <cmath>
#include <functional>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/substitute.hpp"
#include "zeroset/pov/pov_object_parts.hpp"

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

}  // namespace

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

std::optional<Bounds> PovParser::clip_region(const PovObject& clip, const Mat4& to_local, const PovToken& at, RegionUse use) {
    if (!clip.shape) return std::nullopt;
    const Mat4 m = to_local * clip.node->transform;
    const Bounds& s = *clip.shape;
    if (s.kind == Bounds::Kind::Sphere) {
        if (const auto scale = similarity_scale(m)) return Bounds::make_sphere(m.transform_point(s.center), s.radius * *scale);
    } else if (axis_aligned(m)) {
        const Vec3d a = m.transform_point(s.box.lo), z = m.transform_point(s.box.hi);
        return Bounds::make_box({min(a, z), max(a, z)});
    }
    const std::string shape = s.kind == Bounds::Kind::Sphere ? "sphere stretched unevenly" : "turned box";
    if (use == RegionUse::Clip) warn(at, "clipping by a " + shape + " is not supported; clipped by the box around it");
    if (use == RegionUse::Gate)
        warn(at, "bounded_by a " + shape + " is not supported exactly; the surface is seen by the rays that meet the "
                 "box around it, more than POV-Ray's");
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
            if (const auto region = clip_region(*object, m, at, RegionUse::Bounds)) {  // the clip itself is exact
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
        // On an open surface (a polynomial's sheet) POV-Ray's bounded_by
        // decides which rays see it: the object's gate.
        std::optional<Bounds> region;
        if (node->kind == SceneNode::Kind::Object && node->object.open && !b.bounded_by->object->inverse)
            if (const auto into_leaf = node->transform.inverse())
                region = clip_region(*b.bounded_by->object, *into_leaf * b.bounded_by->to_local, b.bounded_by->where,
                                     RegionUse::Gate);
        if (region)
            node->object.gate = *region;
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
