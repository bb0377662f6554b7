// The parts every POV-Ray object reader shares (pov_objects.cpp,
// pov_solids.cpp, pov_primitives.cpp): the builder that collects an
// object's modifiers, the scene nodes objects become, and the solids of a
// ball and a box, which are both shapes and clipping regions.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/expr/substitute.hpp"
#include "zeroset/pov/pov_parser.hpp"

namespace zeroset::pov {

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

/// The solid of a ball, |p − c|² − r², a quadric.
inline Expr ball(const ExprPoint& p, const Vec3d& c, double r) {
    return square(p.x - Expr(c.x)) + square(p.y - Expr(c.y)) + square(p.z - Expr(c.z)) - Expr(r * r);
}

/// The solid of an axis-aligned box of centre c and half-size h: the max of its slabs.
inline Expr slabs(const ExprPoint& p, const Vec3d& c, const Vec3d& h) {
    return max(max(abs(p.x - Expr(c.x)) - Expr(h.x), abs(p.y - Expr(c.y)) - Expr(h.y)), abs(p.z - Expr(c.z)) - Expr(h.z));
}

/// An object node of the scene's tree, named by its POV-Ray keyword.
inline std::shared_ptr<SceneNode> object_node(const PovToken& keyword, const std::string& where) {
    auto node = std::make_shared<SceneNode>();
    node->kind = SceneNode::Kind::Object;
    node->name = keyword.text;
    node->defined_at = where;
    return node;
}

/// The POV-Ray object of a node, named and located by its keyword.
inline std::shared_ptr<PovObject> wrap(const PovToken& keyword, SceneNodePtr node) {
    auto o = std::make_shared<PovObject>();
    o->node = std::move(node);
    o->kind = keyword.text;
    o->where = keyword.where;
    return o;
}

}  // namespace zeroset::pov
