// What a ray query over primitives returns: where the ray meets a boundary of
// a solid (a Hit), which leaf primitive owns that boundary and how to find its
// normal later (a SurfaceRef), and the parts of the ray inside a solid (Roth's
// span lists, survey §7). Normals are computed only for the hit that is
// shaded, so a SurfaceRef keeps what that needs: the point in the leaf's own
// space and the linear map into it, composed by every transform on the way
// up (eq. 36; normals by the inverse transpose, §8).
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/math/mat4.hpp"

namespace zeroset {

class LeafPrimitive;

/// An index into the scene's table of materials; no_material: none given.
using MaterialId = std::int32_t;
inline constexpr MaterialId no_material = -1;

enum class BoundaryKind : std::uint8_t {
    Surface,  // the leaf's surface, f = 0
    Bounds,   // the leaf's bounds, where they cut through its solid
    Open,     // no boundary: the query's own t_min or t_max (the ray starts or ends inside)
};

struct SurfaceRef {
    const LeafPrimitive* leaf = nullptr;  // null only for BoundaryKind::Open
    BoundaryKind kind = BoundaryKind::Open;
    bool flipped = false;                // a subtracted solid's boundary: its normal points the other way
    MaterialId material = no_material;   // the innermost material given
    Vec3d local_point{};                 // the point in the leaf's space
    Mat4 to_local = Mat4::identity();    // from the query's space to the leaf's
    double scale = 1.0;                  // the leaf's size (SearchRegion::scale) in the query's space
};

struct Hit {
    double t;
    SurfaceRef surface;
};

/// The ray is inside the solid from enter.t to exit.t (enter.t ≤ exit.t).
struct InsideSpan {
    Hit enter;
    Hit exit;
};

/// Sorted, disjoint spans.
using SpanList = std::vector<InsideSpan>;

}  // namespace zeroset
