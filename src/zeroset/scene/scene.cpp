// Building and walking the scene's tree.
#include "zeroset/scene/scene.hpp"

namespace zeroset {

Expr surface_of(const Object& object) { return object.blob ? object.blob->field_expression() : object.surface; }

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

}  // namespace zeroset
