// A tile's rays against a box, by projecting the box's corners onto the
// image plane.
#include "zeroset/accel/camera_frustum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zeroset {

bool CameraFrustum::misses(const Box3& box) const {
    if (!box.valid()) return false;  // NaN, or nothing: never culled
    // The dual basis of (forward, right, up): a point's offset from the eye
    // is s·forward + (s·u)·right + (s·v)·up with s = its depth.
    const double det = dot(forward, cross(right, up));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
    const Vec3d to_s = cross(right, up) / det, to_su = cross(up, forward) / det, to_sv = cross(forward, right) / det;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    double u_lo = infinity, u_hi = -infinity, v_lo = infinity, v_hi = -infinity;
    bool all_behind = true, all_in_front = true;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p{(corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                      (corner & 4) ? box.hi.z : box.lo.z};
        const Vec3d w = p - origin;
        const double s = dot(to_s, w);
        all_behind = all_behind && s < 0.0;
        all_in_front = all_in_front && s > 0.0;
        if (!all_in_front) continue;
        const double u = dot(to_su, w) / s, v = dot(to_sv, w) / s;
        u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u);
        v_lo = std::min(v_lo, v), v_hi = std::max(v_hi, v);
    }
    if (all_behind) return true;
    if (!all_in_front) return false;  // the box reaches the eye's plane: its projection is unbounded
    if (!(std::isfinite(u_lo) && std::isfinite(u_hi) && std::isfinite(v_lo) && std::isfinite(v_hi))) return false;
    // The tile's rectangle, and a margin for the rounding of the projection
    // (a few units of its largest coordinate; 1e-9 of it is far more).
    const double tile_u0 = std::min(u0, u0 + columns * du), tile_u1 = std::max(u0, u0 + columns * du);
    const double tile_v0 = std::min(v0, v0 + rows * dv), tile_v1 = std::max(v0, v0 + rows * dv);
    const double margin = 1e-9 * (1.0 + std::max({std::abs(u_lo), std::abs(u_hi), std::abs(v_lo), std::abs(v_hi),
                                                   std::abs(tile_u0), std::abs(tile_u1), std::abs(tile_v0),
                                                   std::abs(tile_v1)}));
    return u_hi < tile_u0 - margin || u_lo > tile_u1 + margin || v_hi < tile_v0 - margin || v_lo > tile_v1 + margin;
}

}  // namespace zeroset
