// Building and walking the scene's tree.
#include "zeroset/scene/scene.hpp"

#include <stdexcept>

namespace zeroset {

bool cone_antialiasing_named(std::string_view name) {
    if (name == antialiasing_names[1]) return true;
    if (name == antialiasing_names[0]) return false;
    throw std::invalid_argument("unknown antialiasing '" + std::string(name) + "' (known: samples, cone)");
}

Expr surface_of(const Object& object) {
    if (object.fractal)
        throw std::invalid_argument(
            "the object is a fractal (" + std::string(fractal_kind_info(object.fractal->parameters().kind).description) +
            "): it has no expression f(x, y, z), only a distance estimate, so it can be rendered but not probed, "
            "sliced, meshed or mapped");
    if (object.sweep)
        throw std::invalid_argument(
            "the object is a sweep (a sphere swept along a curve, " + std::to_string(object.sweep->size()) +
            " segments): it has no expression f(x, y, z), only the polynomials of its segments along a ray, so it "
            "can be rendered but not probed, sliced, meshed or mapped");
    return object.blob ? object.blob->field_expression() : object.surface;
}

SceneNodePtr make_object_node(Object object, std::string name, std::optional<Material> material) {
    auto node = std::make_shared<SceneNode>();
    node->kind = SceneNode::Kind::Object;
    node->name = std::move(name);
    node->object = std::move(object);
    node->material = std::move(material);
    return node;
}

namespace {

void collect(const SceneNode& node, const Mat4& to_scene, const Material& inherited, std::vector<PlacedObject>& out) {
    const Mat4 here = to_scene * node.transform;
    const Material& material = node.material ? *node.material : inherited;
    if (node.kind == SceneNode::Kind::Object) {
        out.push_back({&node, here, material});
        return;
    }
    for (const SceneNodePtr& child : node.children) collect(*child, here, material, out);
}

}  // namespace

std::vector<PlacedObject> placed_objects(const Scene& scene) {
    std::vector<PlacedObject> out;
    for (const SceneNodePtr& node : scene.nodes) collect(*node, Mat4::identity(), Material{}, out);
    return out;
}

PlacedObject find_placed_object(const Scene& scene, const std::optional<std::string>& name) {
    const std::vector<PlacedObject> objects = placed_objects(scene);
    if (objects.empty()) throw std::invalid_argument("the scene has no objects");
    if (!name) return objects.front();
    std::string names;
    for (const PlacedObject& object : objects) {
        if (object.name() == *name) return object;
        const std::string quoted = "'" + object.name() + "'";
        if (!object.name().empty() && names.find(quoted) == std::string::npos)
            names += (names.empty() ? "" : ", ") + quoted;
    }
    throw std::invalid_argument("the scene has no object named '" + *name + "'" +
                                (names.empty() ? std::string(" (its objects have no names)") : " (it has " + names + ")"));
}

Ray to_object_space(const PlacedObject& object, const Ray& ray) {
    const Mat4 to_object = object.to_scene.inverse().value();  // transforms are checked invertible when read
    return {to_object.transform_point(ray.origin), to_object.transform_vector(ray.dir)};
}

}  // namespace zeroset
