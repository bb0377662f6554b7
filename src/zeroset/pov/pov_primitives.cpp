// POV-Ray's objects that become zeroset's own primitives: blobs (the blob
// primitive with POV-Ray's kernel), isosurfaces (an object of their
// function in its container) and sphere sweeps (the sweep primitive).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "zeroset/pov/pov_object_parts.hpp"
#include "zeroset/trace/sweep_path.hpp"

namespace zeroset::pov {

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

}  // namespace zeroset::pov
