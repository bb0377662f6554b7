// `blob "name" { kernel … threshold … component { … } … }` in the scene
// language (docs/scene-language.md#blobs): a blobby object by its kernels
// (expr/blob_model.hpp), read into an object node whose Object carries the
// model.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_parser.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

constexpr std::array<std::string_view, 9> blob_keys{"kernel",  "threshold", "tolerance", "quadratics", "component",
                                                    "method",  "normals",   "partition", "material"};
constexpr std::array<std::string_view, 6> component_keys{"center", "from", "to", "radius", "strength", "blobbiness"};

}  // namespace

struct SceneParser::BlobReading {
    SceneNode& node;
    BlobKernel kernel = BlobKernel::PovRay;
    double threshold = 1.0;
    std::vector<BlobComponent> components;
    std::map<std::string_view, SourceLocation> seen;  // the keys set once
};

SceneNodePtr SceneParser::blob(const Token& keyword) {
    auto node = object_node(keyword);
    BlobReading reading{*node, BlobKernel::PovRay, 1.0, {}, {}};
    in_->expect(TokenKind::LeftBrace);
    while (!in_->accept(TokenKind::RightBrace)) {
        const Token& entry = in_->peek();
        if (entry.kind == TokenKind::End)
            in_->fail(entry.where, "expected '}' to close the blob block opened at " + line_and_column(keyword.where) +
                                       ", but found end of file");
        if (!blob_entry(reading))
            in_->fail_expected("a key (" + join_words(blob_keys, "or") + "), a transform, let, for or '}'");
    }
    if (reading.components.empty()) in_->fail(keyword.where, "a blob needs at least one component");
    if (node->object.blob_quadratics && reading.kernel != BlobKernel::Metaball)
        in_->fail(reading.seen.at("quadratics"),
                  "quadratics (the survey's approximation by quadratic pieces) is for the metaball kernel only");
    if (node->object.blob_quadratics &&
        std::any_of(reading.components.begin(), reading.components.end(), [](const BlobComponent& c) { return c.is_cylinder(); }))
        in_->fail(reading.seen.at("quadratics"), "quadratics (the survey's quadratic pieces) is for round components, not cylinders");
    Object& object = node->object;
    try {
        object.blob = std::make_shared<const BlobModel>(reading.kernel, reading.threshold, std::move(reading.components));
    } catch (const std::invalid_argument& e) {
        in_->fail(keyword.where, std::string("blob: ") + e.what());
    }
    const std::optional<Box3> reach = object.blob->solid_bounds(object.blob_tolerance);
    if (!reach) in_->fail(keyword.where, "a blob needs a component of positive strength (its field never reaches the threshold)");
    if (!std::isfinite(reach->diagonal())) in_->fail(keyword.where, "the blob's reach is wider than a double can measure");
    object.bounds = Bounds::make_box(*reach);
    return node;
}

bool SceneParser::blob_entry(BlobReading& reading) {
    if (body_entry(reading.node, "a component", [this, &reading] { return blob_entry(reading); })) return true;
    const Token& entry = in_->peek();
    if (!is_one_of(blob_keys, entry)) return false;
    const std::string_view word = entry.text;
    if (word != "component") {
        set_once(reading.seen, entry, "blob");
        if (!reading.components.empty() && word == "kernel")
            in_->fail(entry.where, "the kernel must come before the blob's components");
    }
    in_->next();
    Object& object = reading.node.object;
    if (word == "kernel") {
        std::vector<std::string_view> names;
        for (const BlobKernelInfo& k : blob_kernels()) names.push_back(k.name);
        reading.kernel = *blob_kernel_named(choice("kernel", names).text);
    } else if (word == "threshold") {
        const auto [t, where] = number("the threshold");
        if (!(t > 0.0)) in_->fail(where, "the threshold must be positive");
        reading.threshold = t;
    } else if (word == "tolerance") {
        const auto [t, where] = number("the tolerance");
        if (!(t > 0.0 && t < 1.0)) in_->fail(where, "the tolerance must lie strictly between 0 and 1");
        object.blob_tolerance = t;
    } else if (word == "quadratics") {
        object.blob_quadratics = on_off("quadratics");  // checked against the kernel at the blob's end
    } else if (word == "component") {
        if (++objects_ > limits_.objects)
            in_->fail(entry.where, "the scene makes more than " + std::to_string(limits_.objects) +
                                       " objects and blob components");
        reading.components.push_back(blob_component(entry, reading.kernel));
    } else if (word == "method") {
        object.method = method();
    } else if (word == "normals") {
        object.normals = normal_mode();
    } else if (word == "partition") {
        object.partition = partition();
    } else {
        reading.node.material = material(entry);
    }
    return true;
}

BlobComponent SceneParser::blob_component(const Token& keyword, BlobKernel kernel) {
    BlobComponent c;
    SceneNode shape;  // the component's transforms, checked as a node's are
    std::map<std::string_view, SourceLocation> placed;  // center, from, to, transforms: where given
    std::optional<Vec3d> from, to;
    std::vector<std::string_view> keys(component_keys.begin(), component_keys.end());
    keys.insert(keys.end(), transform_keys.begin(), transform_keys.end());
    block(
        keyword, keys,
        [&](const Token& key) {
            if (key.text == "center" || key.text == "from" || key.text == "to" || is_one_of(transform_keys, key))
                placed.emplace(is_one_of(transform_keys, key) ? std::string_view("transform") : std::string_view(key.text),
                               key.where);
            if (is_one_of(transform_keys, key)) {
                add_transform(key, shape);
            } else if (key.text == "center") {
                c.center = vector("the center").value;
            } else if (key.text == "from") {
                from = vector("the cylinder's start").value;
            } else if (key.text == "to") {
                to = vector("the cylinder's end").value;
            } else if (key.text == "radius") {
                const auto [r, where] = number("the radius");
                if (!(r > 0.0)) in_->fail(where, "the radius must be positive");
                c.radius = r;
            } else if (key.text == "strength") {
                const auto [s, where] = number("the strength");
                if (s == 0.0) in_->fail(where, "the strength must not be 0 (leave the component out)");
                c.strength = s;
            } else {
                const auto [b, where] = number("the blobbiness");
                if (kernel != BlobKernel::Blinn) in_->fail(key.where, "blobbiness is a parameter of the blinn kernel only");
                if (!(b < 0.0)) in_->fail(where, "the blobbiness must be negative (Blinn's B < 0)");
                c.blobbiness = b;
            }
        },
        transform_keys);
    c.shape = shape.transform;
    if (from || to) {  // a cylinder: both ends, and nothing that places it otherwise
        const auto given = [&](std::string_view k) { return placed.count(k) != 0; };
        if (!from || !to)
            in_->fail(placed.at(from ? "from" : "to"), "a cylinder component needs both ends: from (x, y, z) to (x, y, z)");
        if (given("center")) in_->fail(placed.at("center"), "a cylinder component has ends (from, to), not a center");
        if (given("transform"))
            in_->fail(placed.at("transform"), "a cylinder component takes no transform: move its ends instead");
        if (*from == *to) in_->fail(placed.at("to"), "the cylinder's ends must differ (a sphere has a center)");
        const double length2 = dot(*to - *from, *to - *from);
        if (!(length2 > 0.0 && std::isfinite(length2)))
            in_->fail(placed.at("to"), std::string("the cylinder is too ") + (length2 > 0.0 ? "long" : "short") +
                                           " to measure: the square of its length is beyond a double");
        c.center = *from;
        c.end = to;
    }
    return c;
}

}  // namespace zeroset
