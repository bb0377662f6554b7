// PreparedScene: the scene's tree compiled once into primitives (accel/) —
// each object's tape, bounds, method and tolerances; instances of a shared
// node share its primitive, so a shape placed a thousand times is compiled
// once — plus the table of materials and the lights. Shared, read-only, by
// every render thread.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/primitive.hpp"
#include "zeroset/render/color_pattern.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

/// What a render may impose on every object, whatever the scene says.
struct ObjectOverrides {
    std::optional<Method> method;
    std::optional<PolynomialSolver> solver;
    std::optional<NormalMode> normals;
    std::optional<Partition> partition;
    /// The image's size: the octrees' depth is chosen for each object's
    /// size on it (0: a default of 512 pixels).
    int image_width = 0;
    int image_height = 0;
    /// Told how long preparations (octree builds) go: (parts done, parts in all).
    std::function<void(int, int)> on_progress;
};

class Blob;

class PreparedScene {
public:
    /// Throws RenderError when an object cannot be traced as asked (e.g. the
    /// polynomial method on a surface that is not a polynomial).
    explicit PreparedScene(const Scene& scene, const ObjectOverrides& overrides = {});

    [[nodiscard]] const Scene& scene() const { return *scene_; }
    /// The whole scene as one primitive.
    [[nodiscard]] const Primitive& root() const { return *root_; }
    /// Every distinct implicit leaf, by id.
    [[nodiscard]] const std::vector<const ImplicitLeaf*>& leaves() const { return leaves_; }
    /// The material of a hit (the default one for no_material).
    [[nodiscard]] const Material& material(MaterialId id) const;
    /// The compiled colour pattern of each material (null where the colour
    /// is constant), by MaterialId; equal patterns share one.
    [[nodiscard]] const std::vector<std::shared_ptr<const ColorPatternTapes>>& color_patterns() const {
        return color_patterns_;
    }
    /// How many distinct objects each method traces ("plane" for half-spaces), in the order of all_methods().
    [[nodiscard]] std::vector<std::pair<std::string, int>> method_counts() const;
    /// The partitioned objects' octrees, e.g. "'bear' lipschitz octree: 8012 cells
    /// (depth 6, built in 0.61 s, 14 MB), 434 → 120 clauses a cell, median L 3.9";
    /// empty when no object is partitioned.
    [[nodiscard]] std::string partition_summary() const;
    /// The blobs traced by their own path, e.g. "'cloud' blob: 1000 povray
    /// components, exact degree-4 polynomials, guarded segments, BVH 450 nodes,
    /// 0.3 MB"; empty when there are none.
    [[nodiscard]] std::string blob_summary() const;
    /// Whether any object is a blob traced by its own path (its camera rays want their tiles).
    [[nodiscard]] bool has_blobs() const { return !blobs_.empty(); }
    /// What the scene may not have meant, e.g. "scene.zs:12:1: object 'ball':
    /// its bounds cut through its solid …" (trace/bounds_cut.hpp).
    [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
    /// The scene's lights, or — when it has none — one white point light at the camera.
    [[nodiscard]] const std::vector<Light>& lights() const { return lights_; }

private:
    std::shared_ptr<const Primitive> prepare(const SceneNodePtr& node);
    /// footprints_ from the camera and the image size.
    void measure_footprints(const Scene& scene);
    MaterialId material_id(const std::optional<Material>& material);
    /// Notes a warning when the object's bounds cut through its solid.
    void warn_of_cut(const SceneNode& node, const std::string& name, const Tape& tape);

    const Scene* scene_;
    ObjectOverrides overrides_;
    std::vector<Light> lights_;
    std::vector<Material> materials_;
    std::vector<std::shared_ptr<const ColorPatternTapes>> color_patterns_;  // parallel to materials_
    std::map<std::array<const void*, 3>, std::shared_ptr<const ColorPatternTapes>> patterns_by_expr_;
    Material default_material_;
    std::vector<const ImplicitLeaf*> leaves_;
    std::vector<std::string> warnings_;
    std::vector<const Blob*> blobs_;
    int fractals_ = 0;
    int sweeps_ = 0;
    double pixel_footprint_ = 0.0;  // CameraRays::footprint_radius, for the fractals' hit tolerance (0: no image)
    int planes_ = 0;
    std::unordered_map<const SceneNode*, std::shared_ptr<const Primitive>> prepared_;  // by node, for sharing
    std::unordered_map<const SceneNode*, int> footprints_;  // an object's largest size on screen, in pixels
    std::shared_ptr<const Primitive> root_;
};

}  // namespace zeroset
