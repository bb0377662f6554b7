// Primitive: everything the renderer traces answers the same questions
// (DESIGN.md, "Primitives"): its bounds, the first hit along a ray, whether
// a shadow ray is blocked, and the spans of the ray inside its solid. The
// kinds are an implicit leaf (a tape and its method), an instance (a shared
// child with its own transform and material), a group (children in a BVH;
// also CSG union) and a CSG intersection or difference (Roth's span lists).
//
// Primitives are prepared once and shared, read-only, by every render
// thread; what a query needs to write — evaluators, root finders, span
// buffers, counters — lives in the thread's TraceScratch. A query costs one
// virtual call per primitive it visits, never one per evaluation. A camera
// tile can be asked as a whole whether its rays all miss (misses_tile).
#pragma once

#include <optional>
#include <string>

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/accel/surface_ref.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {

class TraceScratch;

class Primitive {
public:
    virtual ~Primitive() = default;

    /// A box containing the solid, in the primitive's own (parent's) space;
    /// infinite where the solid is unbounded.
    [[nodiscard]] virtual Box3 bounds() const = 0;

    /// The smallest t in [t_min, t_max] where the ray is on or in the solid
    /// (t_min itself when it starts inside).
    virtual std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const = 0;

    /// Whether any t in [t_min, t_max] is on or in the solid.
    virtual bool occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
        return first_hit(ray, t_min, t_max, scratch).has_value();
    }

    /// Appends the parts of [t_min, t_max] inside the solid to `out`, in
    /// increasing t: a span that starts at t_min because the ray starts
    /// inside has an Open enter, one that runs on past t_max an Open exit.
    virtual void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const = 0;

    /// True when it is proven that no camera ray of the tile (t ≥ 0) meets
    /// the solid: the renderer then gives the tile's pixels the background
    /// without tracing them. False when that is not certain — by default,
    /// unless the tile misses the bounds. Cheap, and asked again as a
    /// tile's rays go (a polynomial leaf proves a tile after a few misses).
    virtual bool misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const {
        (void)scratch;
        return tile.misses(bounds());
    }
};

/// A primitive that owns surfaces — a leaf of the tree: an implicit leaf or
/// a half-space. Every boundary a query reports names its leaf, which gives
/// the normal there when the hit is shaded.
class LeafPrimitive : public Primitive {
public:
    /// The unit outward normal at a boundary point, in the leaf's own space;
    /// the zero vector where it is undefined.
    virtual Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const = 0;
    /// For messages and statistics.
    [[nodiscard]] virtual const std::string& name() const = 0;
};

/// The boundary of `leaf` at `point` (no leaf for BoundaryKind::Open), in
/// the leaf's own space, for an object of size `scale`.
inline SurfaceRef leaf_surface(const LeafPrimitive& leaf, BoundaryKind kind, MaterialId material, const Vec3d& point,
                               double scale) {
    SurfaceRef s;
    s.leaf = kind == BoundaryKind::Open ? nullptr : &leaf;
    s.kind = kind;
    s.material = material;
    s.local_point = point;
    s.scale = scale;
    return s;
}

/// True when every coordinate of the box is finite.
inline bool is_bounded(const Box3& box) {
    return std::isfinite(box.lo.x) && std::isfinite(box.lo.y) && std::isfinite(box.lo.z) && std::isfinite(box.hi.x) &&
           std::isfinite(box.hi.y) && std::isfinite(box.hi.z);
}

}  // namespace zeroset
