// Scene: what to render — camera, lights, background, image settings and the
// implicit objects. Built by the scene-language parser (scene/load_scene.hpp) or
// directly in C++; consumed by the renderer.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/expr/blob_model.hpp"
#include "zeroset/expr/expr.hpp"
#include "zeroset/math/mat4.hpp"
#include "zeroset/math/ray.hpp"
#include "zeroset/math/vec3.hpp"
#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/fractal_estimate.hpp"
#include "zeroset/trace/swept_sphere.hpp"
#include "zeroset/accel/octree.hpp"
#include "zeroset/trace/method.hpp"

namespace zeroset {

/// Pinhole camera looking from `from` towards `at`; `fov_degrees` is the
/// vertical field of view.
struct Camera {
    Vec3d from{0.0, 0.0, -5.0};
    Vec3d at{0.0, 0.0, 0.0};
    Vec3d up{0.0, 1.0, 0.0};
    double fov_degrees = 40.0;
    /// A shifted lens: the image's centre moved off the view axis by these
    /// many image heights, right and up, its plane still at right angles to
    /// at − from (verticals stay parallel; POV-Ray's camera whose direction
    /// leans towards its up or right vector).
    double shift_right = 0.0;
    double shift_up = 0.0;
};

struct Light {
    enum class Kind { Point, Directional };
    Kind kind = Kind::Point;
    Vec3d position{0.0, 0.0, 0.0};   // Kind::Point
    Vec3d direction{0.0, -1.0, 0.0}; // Kind::Directional: the way the light travels
    Vec3d color{1.0, 1.0, 1.0};      // linear RGB radiance scale
    bool casts_shadows = true;
};

/// Blinn–Phong material, with an optional mirror reflection.
struct Material {
    Vec3d color{0.8, 0.8, 0.8};  // diffuse albedo, linear RGB
    /// When set, the colour instead: three expressions of the object's own
    /// coordinates (a checker, stripes, a colour from a function's value),
    /// evaluated at each hit; negative components count as 0.
    std::optional<std::array<Expr, 3>> color_pattern;
    double ambient = 0.1;        // fraction of the scene's ambient light reflected
    double diffuse = 0.9;
    double specular = 0.3;
    double shininess = 40.0;     // Blinn–Phong exponent
    /// The share of the mirror image added to the colour, in [0, 1] (as
    /// POV-Ray's `reflection`): colour + reflection · what the mirrored ray sees.
    double reflection = 0.0;
};

/// Bounds of an object that gives none: the box from (−10, −10, −10) to (10, 10, 10).
inline Bounds default_object_bounds() {
    Bounds b;
    b.box.lo = {-10.0, -10.0, -10.0};
    b.box.hi = {10.0, 10.0, 10.0};
    return b;
}

/// An implicit surface within its bounds, and how to trace it: a leaf of the
/// scene's tree.
struct Object {
    Expr surface;  // f(x, y, z): negative inside, zero on the surface
    Bounds bounds = default_object_bounds();
    Method method = Method::Auto;
    PolynomialSolver solver = PolynomialSolver::Fast;  // for Method::Polynomial
    NormalMode normals = NormalMode::Analytic;
    Partition partition = Partition::Auto;  // spatial partitioning of the bounds (accel/octree.hpp)
    /// A blob (expr/blob_model.hpp) when set: `surface` is then unused (surface_of
    /// writes the field when a general method asks for it) and `bounds` is its reach.
    std::shared_ptr<const BlobModel> blob;
    double blob_tolerance = default_blinn_tolerance;  // Blinn's cut-off, relative to the threshold
    bool blob_quadratics = false;  // metaballs: the survey's quadratic pieces instead of the exact kernel
    /// A fractal (trace/fractal_estimate.hpp) when set, sphere traced by its
    /// distance estimate: `surface` is then unused (it has no expression) and
    /// `bounds` is its ball's box.
    std::shared_ptr<const FractalEstimate> fractal;
    double fractal_detail = 1.0;  // the hit tolerance, in pixel footprints (accel/fractal.hpp)
    /// A swept sphere (trace/swept_sphere.hpp) when set: its Bézier segments,
    /// traced exactly by their polynomials; `surface` is then unused (it has
    /// no expression) and `bounds` is the segments' box.
    std::shared_ptr<const std::vector<SweptSegment>> sweep;
    /// The bounds may cut through the solid on purpose (a cut-away): no
    /// warning when they do (trace/bounds_cut.hpp).
    bool cut_by_bounds = false;
    /// The object is its surface alone, a sheet with no inside: where the
    /// bounds cut it, it is open (LeafDescription::open).
    bool open = false;
    /// An open object is not drawn where this expression is positive
    /// (LeafDescription::clip): POV-Ray's clipped_by.
    std::optional<Expr> clip;
    /// Only rays that pass through these bounds see the object, and those
    /// see all of it within its own bounds (LeafDescription::gate):
    /// POV-Ray's bounded_by on its unbounded surfaces.
    std::optional<Bounds> gate;
};

/// The object's f: its surface, or a blob's field as an expression. Throws
/// std::invalid_argument for a fractal or a sweep, which have none.
Expr surface_of(const Object& object);

struct SceneNode;
using SceneNodePtr = std::shared_ptr<const SceneNode>;

/// A node of the scene's tree: an object, or a group (CSG union), an
/// intersection or a difference (the first child minus the others) of
/// nodes. Nodes are shared: a shape placed many times is one node under
/// several parents, each with its own transform and material (an instance).
struct SceneNode {
    enum class Kind { Object, Group, Intersection, Difference };
    Kind kind = Kind::Group;
    std::string name;                    // for messages, statistics and `zeroset ray --object`
    std::string defined_at;              // "file:line:column" of its statement, for warnings; may be empty
    Object object;                       // Kind::Object
    std::vector<SceneNodePtr> children;  // the other kinds
    Mat4 transform = Mat4::identity();   // from the node's own space to its parent's
    std::optional<Material> material;    // for the parts below that give none
};

/// A node for an object.
SceneNodePtr make_object_node(Object object, std::string name = {}, std::optional<Material> material = {});

/// Image settings a scene may carry; the command line overrides them.
struct ImageSettings {
    int width = 640;
    int height = 480;
    int samples_per_pixel = 1;
    /// Antialias by cone tracing one ray a pixel (render/cone_tracer.hpp)
    /// rather than by samples alone.
    bool cone_antialiasing = false;
    /// How many mirror bounces a camera ray may take (0 to max_reflection_depth);
    /// a ray past them sees black.
    int reflection_depth = 5;
};

/// The ways to antialias, by name: `samples` (by --spp alone) and `cone`.
inline constexpr std::array<std::string_view, 2> antialiasing_names{"samples", "cone"};
/// Whether `name` asks for cone antialiasing; std::invalid_argument
/// ("unknown antialiasing 'X' (known: samples, cone)") for another name.
bool cone_antialiasing_named(std::string_view name);

/// The deepest mirror recursion a render allows (each bounce is a stack frame).
inline constexpr int max_reflection_depth = 64;

struct Scene {
    Camera camera;
    std::vector<Light> lights;
    Vec3d background{0.05, 0.05, 0.08};  // linear RGB
    Vec3d ambient{1.0, 1.0, 1.0};        // ambient light colour (scaled by Material::ambient)
    ImageSettings image;
    std::vector<SceneNodePtr> nodes;  // the top level
    /// What the reader drew differently from what the file asks, located,
    /// e.g. a POV-Ray import's "scene.pov:12:3: … is not supported; rendered
    /// as …"; the render's warnings start with these.
    std::vector<std::string> warnings;
};

/// One placement of an object in the scene: its node, the map from its
/// space to the scene's, and the material it is shaded with.
struct PlacedObject {
    const SceneNode* node;
    Mat4 to_scene;
    Material material;

    [[nodiscard]] const Object& object() const { return node->object; }
    [[nodiscard]] const std::string& name() const { return node->name; }
};

/// Every placement of every object, depth first in the order written.
std::vector<PlacedObject> placed_objects(const Scene& scene);

/// The first placement of the object called `name`, or the scene's first
/// object when no name is given. Throws std::invalid_argument when the scene
/// has no objects, or none of that name (the message lists the names it has).
PlacedObject find_placed_object(const Scene& scene, const std::optional<std::string>& name);

/// A ray given in the scene's space, in the placed object's own space (its
/// transforms undone); t means the same point on both.
Ray to_object_space(const PlacedObject& object, const Ray& ray);

}  // namespace zeroset
