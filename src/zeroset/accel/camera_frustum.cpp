// A tile's rays against a box, by projecting the box's corners onto the
// image plane.
#include "zeroset/accel/camera_frustum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zeroset {

std::optional<CameraFrustum::DualBasis> CameraFrustum::dual_basis() const {
    const double det = dot(forward, cross(right, up));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
    return DualBasis{cross(right, up) / det, cross(up, forward) / det, cross(forward, right) / det};
}

CameraFrustum::Rectangle CameraFrustum::rectangle() const {
    return {std::min(u0, u0 + columns * du), std::max(u0, u0 + columns * du), std::min(v0, v0 + rows * dv),
            std::max(v0, v0 + rows * dv)};
}

double CameraFrustum::Rectangle::margin(double largest) const {
    // A few units of the largest coordinate; 1e-9 of it is far more.
    return 1e-9 * (1.0 + std::max({largest, std::abs(u_lo), std::abs(u_hi), std::abs(v_lo), std::abs(v_hi)}));
}

bool CameraFrustum::misses(const Box3& box) const {
    const auto basis = dual_basis();
    return basis && misses(box, *basis);
}

bool CameraFrustum::misses(const Box3& box, const DualBasis& basis) const {
    if (!box.valid()) return false;  // NaN, or nothing: never culled
    constexpr double infinity = std::numeric_limits<double>::infinity();
    double u_lo = infinity, u_hi = -infinity, v_lo = infinity, v_hi = -infinity;
    bool all_behind = true, all_in_front = true;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p{(corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                      (corner & 4) ? box.hi.z : box.lo.z};
        const Vec3d w = p - origin;
        const double s = dot(basis.to_s, w);
        all_behind = all_behind && s < 0.0;
        all_in_front = all_in_front && s > 0.0;
        if (!all_in_front) continue;
        const double u = dot(basis.to_su, w) / s, v = dot(basis.to_sv, w) / s;
        u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u);
        v_lo = std::min(v_lo, v), v_hi = std::max(v_hi, v);
    }
    if (all_behind) return true;
    if (!all_in_front) return false;  // the box reaches the eye's plane: its projection is unbounded
    if (!(std::isfinite(u_lo) && std::isfinite(u_hi) && std::isfinite(v_lo) && std::isfinite(v_hi))) return false;
    const Rectangle tile = rectangle();
    const double margin = tile.margin(std::max({std::abs(u_lo), std::abs(u_hi), std::abs(v_lo), std::abs(v_hi)}));
    return u_hi < tile.u_lo - margin || u_lo > tile.u_hi + margin || v_hi < tile.v_lo - margin ||
           v_lo > tile.v_hi + margin;
}

bool CameraFrustum::holds(const Ray& ray, const DualBasis& basis) const {
    if (!(ray.origin == origin)) return false;
    const double s = dot(basis.to_s, ray.dir);
    if (!(s > 0.0)) return false;
    const double u = dot(basis.to_su, ray.dir) / s, v = dot(basis.to_sv, ray.dir) / s;
    const Rectangle tile = rectangle();
    // Within half the least margin misses() allows: a box that meets the
    // ray projects over its (u, v), so misses() keeps it for the tile.
    const double margin = 0.5 * tile.margin(0.0);
    return u >= tile.u_lo - margin && u <= tile.u_hi + margin && v >= tile.v_lo - margin && v <= tile.v_hi + margin;
}

}  // namespace zeroset
