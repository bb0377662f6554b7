// The scene tree flattened for distance bounds, and the bounds themselves
// (see scene_distance.hpp).
#include "zeroset/render/scene_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "zeroset/accel/primitive.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/render/render_settings.hpp"

namespace zeroset {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// An upper bound of how much the linear part A of m stretches a length:
/// the square root of Gershgorin's bound of the largest eigenvalue of AᵀA —
/// exact for rotations and scales, a little loose for shears.
double stretch_of(const Mat4& m) {
    const std::array<Vec3d, 3> columns{m.transform_vector({1, 0, 0}), m.transform_vector({0, 1, 0}),
                                       m.transform_vector({0, 0, 1})};
    double largest = 0.0;
    for (const Vec3d& a : columns) {
        double row = 0.0;
        for (const Vec3d& b : columns) row += std::abs(dot(a, b));
        largest = std::max(largest, row);
    }
    return std::sqrt(largest);
}

/// The distance from p to the bounds (0 inside them).
double distance_to_bounds(const Vec3d& p, const Bounds& bounds) {
    if (bounds.kind == Bounds::Kind::None) return 0.0;
    if (bounds.kind == Bounds::Kind::Sphere) return std::max(length(p - bounds.center) - bounds.radius, 0.0);
    double sum = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double gap = std::max({bounds.box.lo[axis] - p[axis], p[axis] - bounds.box.hi[axis], 0.0});
        sum += gap * gap;
    }
    return std::sqrt(sum);
}

/// The point of the bounds nearest p: p itself inside them.
Vec3d nearest_in_bounds(const Vec3d& p, const Bounds& bounds) {
    if (bounds.kind == Bounds::Kind::None) return p;
    if (bounds.kind == Bounds::Kind::Sphere) {
        const Vec3d v = p - bounds.center;
        const double from_center = length(v);
        return from_center <= bounds.radius ? p : bounds.center + v * (bounds.radius / from_center);
    }
    return {std::clamp(p.x, bounds.box.lo.x, bounds.box.hi.x), std::clamp(p.y, bounds.box.lo.y, bounds.box.hi.y),
            std::clamp(p.z, bounds.box.lo.z, bounds.box.hi.z)};
}

/// From p inside the bounds, the distance to their boundary.
double depth_in_bounds(const Vec3d& p, const Bounds& bounds) {
    if (bounds.kind == Bounds::Kind::None) return infinity;
    if (bounds.kind == Bounds::Kind::Sphere) return std::max(bounds.radius - length(p - bounds.center), 0.0);
    double depth = infinity;
    for (int axis = 0; axis < 3; ++axis)
        depth = std::min({depth, p[axis] - bounds.box.lo[axis], bounds.box.hi[axis] - p[axis]});
    return std::max(depth, 0.0);
}

const DistanceBound& smaller(const DistanceBound& a, const DistanceBound& b) { return b.distance < a.distance ? b : a; }
const DistanceBound& larger(const DistanceBound& a, const DistanceBound& b) { return b.distance > a.distance ? b : a; }

}  // namespace

std::unique_ptr<Tape> SceneDistance::bounded_tape(const SceneNode& node) {
    const Object& object = node.object;
    const auto refuse = [&](const std::string& size) {
        const std::string name = node.name.empty() ? "an object" : "object '" + node.name + "'";
        throw RenderError(name + " has " + size + ": cone antialiasing bounds an object's whole function at every "
                          "step, and takes functions of at most " + std::to_string(max_clauses) +
                          " operations and blobs of at most " + std::to_string(max_blob_components) +
                          " components; antialias this scene with samples (--spp) instead");
    };
    if (object.fractal)
        throw RenderError((node.name.empty() ? std::string("an object") : "object '" + node.name + "'") +
                          " is a fractal: cone antialiasing needs a bound on each object's distance, and a "
                          "fractal has only an estimate; antialias this scene with samples (--spp) instead");
    if (object.sweep)
        throw RenderError((node.name.empty() ? std::string("an object") : "object '" + node.name + "'") +
                          " is a sweep: cone antialiasing bounds each object's distance through its expression, and "
                          "a sweep has none; antialias this scene with samples (--spp) instead");
    // A blob's field is a sum over its components: refused before it is built.
    if (object.blob && object.blob->components().size() > max_blob_components)
        refuse(std::to_string(object.blob->components().size()) + " blob components");
    auto tape = std::make_unique<Tape>(surface_of(object));
    if (tape->clauses().size() > max_clauses) refuse(std::to_string(tape->clauses().size()) + " operations");
    return tape;
}

SceneDistance::SceneDistance(const Scene& scene) {
    reach_ = empty_box();
    std::unordered_map<const SceneNode*, int> tape_of;
    for (const SceneNodePtr& node : scene.nodes) roots_.push_back(add(*node, Mat4::identity(), tape_of));
    for (const int root : roots_) {
        all_roots_.push_back(static_cast<int>(root_boxes_.size()));
        root_boxes_.push_back(box_of(root));
    }
}

int SceneDistance::add(const SceneNode& scene_node, const Mat4& to_scene,
                       std::unordered_map<const SceneNode*, int>& tape_of) {
    const Mat4 here = to_scene * scene_node.transform;
    Node node{scene_node.kind, here.inverse().value_or(Mat4::identity()), here, 1.0, {}, -1, {}};
    node.stretch = stretch_of(node.to_local);
    if (scene_node.kind == SceneNode::Kind::Object) {
        const Object& object = scene_node.object;
        node.bounds = object.bounds;
        // One tape for each distinct object, however often it is placed.
        const auto [it, fresh] = tape_of.emplace(&scene_node, static_cast<int>(tapes_.size()));
        if (fresh) tapes_.push_back(bounded_tape(scene_node));
        node.tape = it->second;
        const Box3 box = object.bounds.enclosing_box();
        if (is_bounded(box)) reach_ = united(reach_, here.transform_box(box));
    }
    const int index = static_cast<int>(nodes_.size());
    nodes_.push_back(std::move(node));
    for (const SceneNodePtr& child : scene_node.children) {
        const int c = add(*child, here, tape_of);
        nodes_[static_cast<std::size_t>(index)].children.push_back(c);
    }
    return index;
}

Box3 SceneDistance::box_of(int index) const {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    if (node.kind == SceneNode::Kind::Object) return node.to_scene.transform_box(node.bounds.enclosing_box());
    if (node.children.empty()) return empty_box();
    Box3 box = box_of(node.children.front());
    if (node.kind == SceneNode::Kind::Difference) return box;  // within the first child
    for (std::size_t i = 1; i < node.children.size(); ++i) {
        const Box3 child = box_of(node.children[i]);
        box = node.kind == SceneNode::Kind::Group ? united(box, child) : overlap(box, child);
    }
    return box;
}

DistanceProbe::DistanceProbe(const SceneDistance& scene) : scene_(&scene) {
    for (const auto& tape : scene.tapes_) {
        values_.emplace_back(*tape);
        enclosures_.emplace_back(*tape);
        slopes_.emplace_back(*tape);
        gradients_.emplace_back(*tape);
    }
}

DistanceBound DistanceProbe::outside_at(const Vec3d& p, double reach) { return outside_at(p, reach, scene_->all_roots_); }

DistanceBound DistanceProbe::inside_at(const Vec3d& p, double reach) { return inside_at(p, reach, scene_->all_roots_); }

DistanceBound DistanceProbe::outside_at(const Vec3d& p, double reach, std::span<const int> roots) {
    DistanceBound best{reach, -1, false, false};
    for (const int root : roots) {
        const auto i = static_cast<std::size_t>(root);
        // A box no nearer than the nearest so far holds nothing nearer.
        if (distance_to_bounds(p, Bounds::make_box(scene_->root_boxes_[i])) >= best.distance) continue;
        best = smaller(best, node_at(scene_->roots_[i], p, best.distance, true).outside);
    }
    return best;
}

DistanceBound DistanceProbe::inside_at(const Vec3d& p, double reach, std::span<const int> roots) {
    DistanceBound deepest{0.0, -1, true, false};
    for (const int root : roots) {
        const auto i = static_cast<std::size_t>(root);
        if (scene_->root_boxes_[i].contains(p))  // only a solid's box holds points inside it
            deepest = larger(deepest, node_at(scene_->roots_[i], p, reach, false).inside);
    }
    return deepest;
}

bool DistanceProbe::holds_no_solid(const Box3& box, std::span<const int> roots) {
    for (const int root : roots) {
        const auto i = static_cast<std::size_t>(root);
        if (overlap(box, scene_->root_boxes_[i]).valid() && !node_holds_none(scene_->roots_[i], box)) return false;
    }
    return true;
}

bool DistanceProbe::node_holds_none(int index, const Box3& box) {
    const SceneDistance::Node& node = scene_->nodes_[static_cast<std::size_t>(index)];
    if (node.kind == SceneNode::Kind::Object) {
        const Box3 local = overlap(node.to_local.transform_box(box), node.bounds.enclosing_box());
        if (!local.valid()) return true;
        const Interval f = enclosures_[static_cast<std::size_t>(node.tape)](
            Interval(local.lo.x, local.hi.x), Interval(local.lo.y, local.hi.y), Interval(local.lo.z, local.hi.z));
        ++evaluations_;
        return !f.is_empty() && f.lo > 0.0;  // undefined somewhere: unsure
    }
    if (node.children.empty()) return true;
    switch (node.kind) {
        case SceneNode::Kind::Group:  // a union: none of its parts
            for (const int child : node.children)
                if (!node_holds_none(child, box)) return false;
            return true;
        case SceneNode::Kind::Intersection:  // within each part
            for (const int child : node.children)
                if (node_holds_none(child, box)) return true;
            return false;
        default:  // a difference: within its first part
            return node_holds_none(node.children.front(), box);
    }
}

DistanceProbe::Pair DistanceProbe::node_at(int index, const Vec3d& p, double reach, bool only_outside) {
    const SceneDistance::Node& node = scene_->nodes_[static_cast<std::size_t>(index)];
    if (node.kind == SceneNode::Kind::Object) return leaf_at(index, p, reach);
    Pair pair{{reach, -1, false, false}, {0.0, -1, true, false}};
    bool first = true;
    for (const int child : node.children) {
        // For the distance to it, a union only needs what is nearer than the
        // nearest so far (the bounds inside then stop at that reach, still true).
        const bool nearer = only_outside && node.kind == SceneNode::Kind::Group;
        const Pair c = node_at(child, p, nearer ? pair.outside.distance : reach, only_outside);
        if (first) {
            pair = c;
            first = false;
        } else if (node.kind == SceneNode::Kind::Group) {
            pair = {smaller(pair.outside, c.outside), larger(pair.inside, c.inside)};
        } else if (node.kind == SceneNode::Kind::Intersection) {
            pair = {larger(pair.outside, c.outside), smaller(pair.inside, c.inside)};
        } else {  // Difference: the first child less this one, i.e. within its complement
            pair = {larger(pair.outside, c.inside), smaller(pair.inside, c.outside)};
        }
    }
    return pair;
}

DistanceProbe::Pair DistanceProbe::leaf_at(int index, const Vec3d& p, double reach) {
    const SceneDistance::Node& node = scene_->nodes_[static_cast<std::size_t>(index)];
    const Vec3d q = node.to_local.transform_point(p);
    const double local_reach = reach * node.stretch;
    const auto in_scene = [&](double local, bool complement, bool by_bounds) {
        return DistanceBound{local / node.stretch, index, complement, by_bounds};
    };
    const DistanceBound none_inside = in_scene(0.0, true, false);
    const double outside_bounds = distance_to_bounds(q, node.bounds);
    if (outside_bounds >= local_reach) return {in_scene(outside_bounds, false, true), none_inside};

    const auto tape = static_cast<std::size_t>(node.tape);
    const Vec3d r{local_reach, local_reach, local_reach};
    const Box3 near = overlap({q - r, q + r}, node.bounds.enclosing_box());  // where the solid within reach lies
    const double slope = lipschitz_bound(slopes_[tape], near).constant;
    // f at the bounds' point nearest q (q itself inside them). Every point s
    // of the convex bounds has |q − s|² ≥ |q − c|² + |c − s|², and the way
    // from c to s stays in the bounds and the ball, where the slope holds.
    const Vec3d c = nearest_in_bounds(q, node.bounds);
    const double f = values_[tape](c.x, c.y, c.z);
    evaluations_ += 2;
    if (std::isnan(f)) return {{0.0, -1, false, false}, {0.0, -1, true, false}};  // nothing is known here
    const double clear = slope > 0.0 ? std::min(std::abs(f) / slope, local_reach) : local_reach;
    if (outside_bounds > 0.0 || f > 0.0) {
        const double by_function = f > 0.0 ? clear : 0.0;
        const double distance = std::min(std::hypot(outside_bounds, by_function), local_reach);
        return {in_scene(distance, false, outside_bounds >= by_function), none_inside};
    }
    const double depth = depth_in_bounds(q, node.bounds);
    return {in_scene(0.0, false, false), in_scene(std::min(clear, depth), true, depth < clear)};
}

namespace {

/// From q, the way to the bounds' nearest point (outside them) or nearest
/// face (inside them), in the bounds' space.
Vec3d toward_bounds(const Vec3d& q, const Bounds& bounds, bool inside) {
    if (bounds.kind == Bounds::Kind::Sphere) return inside ? q - bounds.center : bounds.center - q;
    if (bounds.kind == Bounds::Kind::None) return {};
    const Box3& box = bounds.box;
    if (!inside) {
        Vec3d v;
        for (int axis = 0; axis < 3; ++axis) v[axis] = std::clamp(q[axis], box.lo[axis], box.hi[axis]) - q[axis];
        return v;
    }
    Vec3d v;
    double nearest = infinity;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
            const double gap = side < 0.0 ? q[axis] - box.lo[axis] : box.hi[axis] - q[axis];
            if (gap >= nearest) continue;
            nearest = gap;
            v = {};
            v[axis] = side;
        }
    return v;
}

}  // namespace

Vec3d DistanceProbe::toward_surface(const Vec3d& p, const DistanceBound& bound) {
    if (bound.leaf < 0) return {};
    const SceneDistance::Node& node = scene_->nodes_[static_cast<std::size_t>(bound.leaf)];
    const Vec3d q = node.to_local.transform_point(p);
    Vec3d way;
    if (bound.by_bounds) {
        way = node.to_scene.transform_vector(toward_bounds(q, node.bounds, bound.complement));
    } else {
        const Dual<double> f = evaluate_gradient(gradients_[static_cast<std::size_t>(node.tape)], q);
        ++evaluations_;
        const Vec3d g = node.to_local.transpose_transform_vector({f.g.x, f.g.y, f.g.z});
        way = bound.complement ? g : -g;
    }
    const double len = length(way);
    if (!(len > 0.0) || !std::isfinite(len)) return {};
    return way / len;
}

}  // namespace zeroset
