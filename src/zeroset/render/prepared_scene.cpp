// From the scene's tree to primitives: objects become implicit leaves,
// groups BVHs, intersections and differences CSG nodes, and a transform or
// a material on a node an instance around its primitive.
#include "zeroset/render/prepared_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/csg.hpp"
#include "zeroset/accel/fractal.hpp"
#include "zeroset/accel/group.hpp"
#include "zeroset/accel/half_space.hpp"
#include "zeroset/accel/instance.hpp"
#include "zeroset/accel/swept_sphere.hpp"
#include "zeroset/expr/gaussian_sum.hpp"
#include "zeroset/render/camera_rays.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/trace/bounds_cut.hpp"

namespace zeroset {

PreparedScene::PreparedScene(const Scene& scene, const ObjectOverrides& overrides)
    : scene_(&scene), overrides_(overrides), lights_(scene.lights) {
    if (lights_.empty()) lights_.push_back({Light::Kind::Point, scene.camera.from, {}, {1.0, 1.0, 1.0}, true});
    if (overrides.image_width > 0 && overrides.image_height > 0) {
        measure_footprints(scene);
        pixel_footprint_ = CameraRays(scene.camera, overrides.image_width, overrides.image_height).footprint_radius();
    }
    std::vector<std::shared_ptr<const Primitive>> top;
    top.reserve(scene.nodes.size());
    for (const SceneNodePtr& node : scene.nodes) top.push_back(prepare(node));
    root_ = top.size() == 1 ? top.front() : std::make_shared<Group>(std::move(top));
    prepared_.clear();
}

void PreparedScene::measure_footprints(const Scene& scene) {
    // The corners of each placement's bounds, projected; the largest over
    // the placements of a shared object. An object reaching behind the eye,
    // or far past the image, counts as twice the image's side.
    const int side = std::max(overrides_.image_width, overrides_.image_height);
    const CameraRays camera(scene.camera, overrides_.image_width, overrides_.image_height);
    for (const PlacedObject& placed : placed_objects(scene)) {
        if (placed.object().bounds.kind == Bounds::Kind::None) continue;
        const Box3 box = placed.object().bounds.enclosing_box();
        std::array<Vec3d, 8> corners;
        for (int c = 0; c < 8; ++c)
            corners[static_cast<std::size_t>(c)] = placed.to_scene.transform_point(
                {c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z});
        double extent = camera.pixel_extent(corners);
        if (!(extent >= 0.0)) extent = 2.0 * side;  // NaN: a degenerate camera basis
        extent = std::clamp(extent, 1.0, 2.0 * side);
        int& footprint = footprints_[placed.node];
        footprint = std::max(footprint, static_cast<int>(std::ceil(extent)));
    }
}

const Material& PreparedScene::material(MaterialId id) const {
    return id == no_material ? default_material_ : materials_.at(static_cast<std::size_t>(id));
}

std::string PreparedScene::partition_summary() const {
    std::string text;
    for (const ImplicitLeaf* leaf : leaves_) {
        const Octree* octree = leaf->octree();
        if (!octree) continue;
        const OctreeStats& s = octree->stats();
        char buffer[320];
        std::snprintf(buffer, sizeof buffer,
                      "'%s' %s octree: %zu cells (depth %d, built in %.2f s, %.1f MB), %zu → %.0f clauses a cell, "
                      "median L %.3g",
                      leaf->name().c_str(), std::string(partition_name(leaf->partition())).c_str(), s.cells, s.depth,
                      s.build_seconds, static_cast<double>(s.bytes) / 1e6, s.full_clauses, s.mean_cell_clauses,
                      s.median_lipschitz);
        text += (text.empty() ? "" : "; ") + std::string(buffer);
    }
    return text;
}

std::string PreparedScene::blob_summary() const {
    std::string text;
    for (const Blob* blob : blobs_) {
        const BlobStats& s = blob->stats();
        const BlobKernelInfo& kernel = blob_kernel_info(blob->model().kernel());
        const std::string solved = blob->quadratics()          ? "the survey's quadratic pieces (approximate)"
                                   : kernel.polynomial.empty() ? "interval isolation"
                                                               : "exact degree-" + std::to_string(2 * (kernel.polynomial.size() - 1)) +
                                                                     " polynomials, guarded";
        char buffer[320];
        std::snprintf(buffer, sizeof buffer, "'%s' blob%s: %zu %s components, %s segments, BVH %zu nodes, %.1f MB",
                      blob->name().c_str(), blob->from_expression() ? " (a sum of Gaussians, recognised)" : "",
                      s.components, std::string(kernel.name).c_str(), solved.c_str(),
                      s.bvh_nodes, static_cast<double>(s.bytes) / 1e6);
        text += (text.empty() ? "" : "; ") + std::string(buffer);
        if (!kernel.finite_support) {
            std::snprintf(buffer, sizeof buffer, " (Gaussians cut off at %.3g R, below %.3g of the threshold)",
                          s.reach_radius, blob->tolerance());
            text += buffer;
        }
    }
    return text;
}

std::vector<std::pair<std::string, int>> PreparedScene::method_counts() const {
    std::vector<std::pair<std::string, int>> counts;
    for (const Method m : all_methods()) {
        const auto n = std::ranges::count_if(leaves_, [m](const ImplicitLeaf* leaf) { return leaf->method() == m; });
        if (n > 0) counts.emplace_back(std::string(method_name(m)), static_cast<int>(n));
    }
    if (planes_ > 0) counts.emplace_back("plane", planes_);
    if (!blobs_.empty()) counts.emplace_back("blob", static_cast<int>(blobs_.size()));
    if (fractals_ > 0) counts.emplace_back("fractal", fractals_);
    if (sweeps_ > 0) counts.emplace_back("sweep", sweeps_);
    return counts;
}

MaterialId PreparedScene::material_id(const std::optional<Material>& material) {
    if (!material) return no_material;
    materials_.push_back(*material);
    std::shared_ptr<const ColorPatternTapes> pattern;
    if (const auto& rgb = material->color_pattern) {
        // Expressions are hash-consed: equal patterns (a loop's objects, say) have equal ids.
        auto& shared = patterns_by_expr_[{rgb->at(0).id(), rgb->at(1).id(), rgb->at(2).id()}];
        if (!shared) shared = std::make_shared<const ColorPatternTapes>(*rgb);
        pattern = shared;
    }
    color_patterns_.push_back(std::move(pattern));
    return static_cast<MaterialId>(materials_.size() - 1);
}

void PreparedScene::warn_of_cut(const SceneNode& node, const std::string& name, const Tape& tape) {
    const auto cut = find_bounds_cut(tape, node.object.bounds);
    if (!cut) return;
    char point[128];
    std::snprintf(point, sizeof point, "(%.6g, %.6g, %.6g)", cut->point.x, cut->point.y, cut->point.z);
    warnings_.push_back((node.defined_at.empty() ? "" : node.defined_at + ": ") + "object '" + name +
                        "': its bounds cut through its solid: f < 0 at " + point + " on " + cut->where +
                        " (in its own coordinates), so the bounds are drawn there as a flat face. Enlarge the "
                        "bounds, or say `cut on` in the object if the cut is meant");
}

std::shared_ptr<const Primitive> PreparedScene::prepare(const SceneNodePtr& node) {
    if (const auto known = prepared_.find(node.get()); known != prepared_.end()) return known->second;

    std::shared_ptr<const Primitive> primitive;
    MaterialId around = material_id(node->material);  // what an instance around the primitive gives
    std::string label = node->name.empty() ? "a group" : "'" + node->name + "'";  // for messages
    switch (node->kind) {
        case SceneNode::Kind::Object: {
            const Object& o = node->object;
            // An unnamed one is numbered among all the objects prepared so far.
            const std::string name = node->name.empty()
                                         ? "#" + std::to_string(leaves_.size() + blobs_.size() + static_cast<std::size_t>(planes_ + fractals_ + sweeps_) + 1)
                                         : node->name;
            label = "object '" + name + "'";
            const Method method = overrides_.method.value_or(o.method);
            if (o.fractal) {  // sphere traced by its estimate: no method applies
                if (method != Method::Auto && method != Method::Sphere)
                    throw RenderError("object '" + name + "' is a fractal, sphere traced by its distance estimate: the " +
                                      std::string(method_name(method)) + " method needs an expression it does not have");
                FractalDescription f;
                f.name = name;
                f.estimate = o.fractal;
                f.material = around;
                f.footprint = pixel_footprint_;
                f.detail = o.fractal_detail;
                around = no_material;
                try {
                    primitive = std::make_shared<const Fractal>(std::move(f));
                } catch (const std::invalid_argument& e) {
                    throw RenderError("fractal '" + name + "': " + e.what());
                }
                ++fractals_;
                break;
            }
            if (o.sweep) {  // exact by its polynomials: no method applies
                if (method != Method::Auto && method != Method::Polynomial)
                    throw RenderError("object '" + name + "' is a sweep, traced exactly by its segments' polynomials: the " +
                                      std::string(method_name(method)) + " method needs an expression it does not have");
                std::vector<std::shared_ptr<const Primitive>> segments;
                for (const SweptSegment& s : *o.sweep)
                    segments.push_back(std::make_shared<const SweptSphere>(name, s, around));
                around = no_material;
                primitive = segments.size() == 1 ? segments.front() : std::make_shared<Group>(std::move(segments));
                ++sweeps_;
                break;
            }
            // A sum of Gaussians written out is Blinn's blob: traced as one,
            // within the object's bounds.
            std::shared_ptr<const BlobModel> recognised;
            const Partition partition = overrides_.partition.value_or(o.partition);
            if (!o.blob && method == Method::Auto && partition == Partition::Auto && !o.open && !o.clip && !o.gate &&
                o.bounds.kind != Bounds::Kind::None)
                if (auto model = gaussian_sum_as_blob(o.surface))
                    recognised = std::make_shared<const BlobModel>(std::move(*model));
            if ((o.blob || recognised) && method == Method::Auto) {  // the blob's own path
                BlobDescription b;
                b.name = name;
                b.model = recognised ? recognised : o.blob;
                b.from_expression = recognised != nullptr;
                if (recognised) b.clip = o.bounds;
                b.material = around;
                b.tolerance = o.blob_tolerance;
                b.metaball_quadratics = o.blob_quadratics;
                std::shared_ptr<const Blob> blob;
                try {
                    blob = std::make_shared<const Blob>(std::move(b));
                } catch (const std::invalid_argument& e) {
                    // A sum of Gaussians the blob cannot take (no positive
                    // term, a reach beyond doubles) is traced as written.
                    if (!recognised) throw RenderError("blob '" + name + "': " + e.what());
                }
                if (blob) {
                    if (recognised && !o.cut_by_bounds) warn_of_cut(*node, name, Tape(o.surface));
                    around = no_material;
                    blobs_.push_back(blob.get());
                    primitive = std::move(blob);
                    break;
                }
            }
            LeafDescription d;
            d.name = name;
            d.surface = surface_of(o);
            d.bounds = o.bounds;
            d.method = method;
            d.solver = overrides_.solver.value_or(o.solver);
            d.normals = overrides_.normals.value_or(o.normals);
            d.partition = partition;
            d.open = o.open;
            d.clip = o.clip;
            d.gate = o.gate;
            if (const auto f = footprints_.find(node.get()); f != footprints_.end()) d.footprint_pixels = f->second;
            d.on_octree_progress = overrides_.on_progress;
            d.material = around;
            around = no_material;  // the leaf's own
            try {
                if (o.bounds.kind == Bounds::Kind::None) {
                    if (o.gate) throw RenderError("object '" + name + "': a gate needs bounds (without, it is a half-space)");
                    primitive = std::make_shared<const HalfSpace>(name, o.surface, d.material);
                    ++planes_;
                } else {
                    auto leaf = std::make_shared<const ImplicitLeaf>(leaves_.size(), std::move(d));
                    if (!o.cut_by_bounds && !o.open) warn_of_cut(*node, name, leaf->tape());
                    leaves_.push_back(leaf.get());
                    primitive = std::move(leaf);
                }
            } catch (const std::invalid_argument& e) {
                throw RenderError("object '" + name + "': " + e.what());
            }
            break;
        }
        case SceneNode::Kind::Group: {
            std::vector<std::shared_ptr<const Primitive>> children;
            for (const SceneNodePtr& child : node->children) children.push_back(prepare(child));
            primitive = children.size() == 1 ? children.front() : std::make_shared<Group>(std::move(children));
            break;
        }
        case SceneNode::Kind::Intersection:
        case SceneNode::Kind::Difference: {
            std::vector<std::shared_ptr<const Primitive>> children;
            for (const SceneNodePtr& child : node->children) children.push_back(prepare(child));
            const auto op = node->kind == SceneNode::Kind::Intersection ? CsgNode::Operation::Intersection
                                                                        : CsgNode::Operation::Difference;
            primitive = std::make_shared<CsgNode>(op, std::move(children));
            break;
        }
    }
    if (!node->transform.is_identity() || around != no_material) {
        try {
            primitive = std::make_shared<Instance>(std::move(primitive), node->transform, around);
        } catch (const std::invalid_argument& e) {
            throw RenderError(label + ": " + e.what());
        }
    }
    prepared_.emplace(node.get(), primitive);
    return primitive;
}

}  // namespace zeroset
