// A tile's rays against a box, by the frustum's planes: a box wholly
// outside one of them meets no ray of the tile.
#include "zeroset/accel/camera_frustum.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace zeroset {

std::uint64_t CameraFrustum::new_serial() {
    static std::atomic<std::uint64_t> last{0};
    return last.fetch_add(1, std::memory_order_relaxed) + 1;
}

std::optional<CameraFrustum::DualBasis> CameraFrustum::dual_basis() const {
    const double det = dot(forward, cross(right, up));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
    return DualBasis{cross(right, up) / det, cross(up, forward) / det, cross(forward, right) / det};
}

std::optional<Span> CameraFrustum::depths_of(const Box3& box) const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p{(corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                      (corner & 4) ? box.hi.z : box.lo.z};
        const double s = depth_of(p);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
    return Span{lo, hi};
}

CameraFrustum::Rectangle CameraFrustum::rectangle() const {
    return {std::min(u0, u0 + columns * du), std::max(u0, u0 + columns * du), std::min(v0, v0 + rows * dv),
            std::max(v0, v0 + rows * dv)};
}

double CameraFrustum::Rectangle::margin() const {
    // A few units of the rectangle's coordinates; 1e-9 of them is far more.
    return 1e-9 * (1.0 + std::max({std::abs(u_lo), std::abs(u_hi), std::abs(v_lo), std::abs(v_hi)}));
}

CameraFrustum::Rectangle CameraFrustum::widened_rectangle() const {
    const Rectangle tile = rectangle();
    const double m = tile.margin();  // holds() lets a ray stray by half of it
    return {tile.u_lo - m, tile.u_hi + m, tile.v_lo - m, tile.v_hi + m};
}

CameraFrustum::Planes CameraFrustum::planes(const DualBasis& basis) const {
    const Rectangle w = widened_rectangle();
    const Vec3d &s = basis.to_s, &su = basis.to_su, &sv = basis.to_sv;
    return {{su - s * w.u_lo, s * w.u_hi - su, sv - s * w.v_lo, s * w.v_hi - sv, s}};
}

bool CameraFrustum::misses(const Box3& box) const {
    const auto basis = dual_basis();
    return basis && misses(box, planes(*basis));
}

bool CameraFrustum::misses(const Box3& box, const Planes& planes) const {
    if (!box.valid()) return false;  // NaN, or nothing: never culled
    const Vec3d lo = box.lo - origin, hi = box.hi - origin;
    Vec3d magnitude;  // what the offsets' rounding is relative to
    for (int axis = 0; axis < 3; ++axis)
        magnitude[axis] = std::abs(box.lo[axis]) + std::abs(box.hi[axis]) + 2.0 * std::abs(origin[axis]);
    for (const Vec3d& n : planes.forms) {
        // The form's largest value over the box, and a bound far above its rounding.
        double most = 0.0, size = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            most += std::max(n[axis] * lo[axis], n[axis] * hi[axis]);
            size += std::abs(n[axis]) * magnitude[axis];
        }
        // Endless boxes give ∞ − ∞ or 0·∞: NaN compares false, never culled.
        // (The products may underflow, by half the least subnormal each.)
        if (most < -1e-12 * size - 4.0 * std::numeric_limits<double>::denorm_min()) return true;
    }
    return false;
}

double CameraFrustum::distance_outside(const Vec3d& a, const Vec3d& b, const Planes& planes) const {
    const Vec3d wa = a - origin, wb = b - origin;
    // The rounding of w, of each product and of the division is a few units
    // of |n|·(|a| + |b| + |origin|) over |n|: far below this.
    const double slack = 1e-9 * (max_abs(a) + max_abs(b) + max_abs(origin));
    double farthest = 0.0;
    for (const Vec3d& n : planes.forms) {
        // How far beyond the plane is affine along the segment: least at an end.
        const double beyond = -std::max(dot(n, wa), dot(n, wb)) / length(n) - slack;
        if (beyond > farthest) farthest = beyond;  // NaN (n = 0, endless points) proves nothing
    }
    return farthest;
}

std::optional<CameraFrustum::RayCheck> CameraFrustum::ray_check() const {
    const auto basis = dual_basis();
    if (!basis) return std::nullopt;
    // Within half the least margin misses() allows: a box that meets the
    // ray projects over its (u, v), so misses() keeps it for the tile.
    const Rectangle tile = rectangle();
    const double margin = 0.5 * tile.margin();
    return RayCheck{*basis, {tile.u_lo - margin, tile.u_hi + margin, tile.v_lo - margin, tile.v_hi + margin}};
}

bool CameraFrustum::holds(const Ray& ray, const RayCheck& check) const {
    if (!(ray.origin == origin)) return false;
    const double s = dot(check.basis.to_s, ray.dir);
    if (!(s > 0.0)) return false;
    const double u = dot(check.basis.to_su, ray.dir) / s, v = dot(check.basis.to_sv, ray.dir) / s;
    const Rectangle& r = check.accepted;
    return u >= r.u_lo && u <= r.u_hi && v >= r.v_lo && v <= r.v_hi;
}

}  // namespace zeroset
