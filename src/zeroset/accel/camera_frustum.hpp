// CameraFrustum: the camera rays of one image tile, for culling the tile's
// empty space before any ray is traced (accel/frustum_cull.hpp; issue 10's
// image-space culling, as fidget and MPR do it). Each ray of pixel (i, j)
// of the tile leaves `origin` along a positive multiple of
// forward + u·right + v·up, with (u, v) inside the pixel's rectangle of
// the image plane; the ray's point at depth s is origin + s·(forward +
// u·right + v·up). An instance carries the frustum into its child's space:
// an affine map keeps the rays straight and their depths, so a leaf sees
// the tile's rays in its own coordinates.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "zeroset/math/box3.hpp"
#include "zeroset/math/mat4.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct CameraFrustum {
    Vec3d origin, forward, right, up;
    // Pixel (i, j) covers u between u0 + i·du and u0 + (i + 1)·du, and v
    // between v0 + j·dv and v0 + (j + 1)·dv (either step may be negative).
    double u0 = 0.0, du = 0.0, v0 = 0.0, dv = 0.0;
    int columns = 0, rows = 0;
    /// Names the frustum: each one made (new_serial) has its own, a copy
    /// keeps it, so equal serials mean equal frusta; 0: unnamed.
    std::uint64_t serial = 0;

    bool operator==(const CameraFrustum&) const = default;
    /// The same frustum: by serial when named (one comparison), else field by field.
    [[nodiscard]] bool same_as(const CameraFrustum& o) const { return serial != 0 ? serial == o.serial : *this == o; }
    /// A serial no frustum has had yet (thread-safe).
    static std::uint64_t new_serial();

    [[nodiscard]] int pixels() const { return columns * rows; }
    /// The same rays in the space that `to_child` maps this one into (a
    /// new frustum, with a serial of its own).
    [[nodiscard]] CameraFrustum in_child_space(const Mat4& to_child) const {
        CameraFrustum c = *this;
        c.origin = to_child.transform_point(origin);
        c.forward = to_child.transform_vector(forward);
        c.right = to_child.transform_vector(right);
        c.up = to_child.transform_vector(up);
        c.serial = new_serial();
        return c;
    }
    /// The point at depth s on the ray through (u, v).
    [[nodiscard]] Vec3d at(double s, double u, double v) const { return origin + (forward + right * u + up * v) * s; }
    /// The depth of point p: the s with p on the plane of the points at
    /// depth s (the linear form that is 1 on `forward` and 0 on `right`
    /// and `up`).
    [[nodiscard]] double depth_of(const Vec3d& p) const { return dot(depth_form(), p - origin); }
    /// The least and largest depth of the box's points: depth is linear, so
    /// its corners' (as rounded; callers widen them). Nothing when either
    /// is not finite.
    [[nodiscard]] std::optional<Span> depths_of(const Box3& box) const;
    /// How fast depth grows along direction d: a ray's depth is t times this.
    [[nodiscard]] double depth_rate(const Vec3d& d) const { return dot(depth_form(), d); }
    /// The dual basis of (forward, right, up): a point's offset w from the
    /// eye is s·forward + (s·u)·right + (s·v)·up with s = to_s·w, s·u =
    /// to_su·w and s·v = to_sv·w. Nothing when the three are degenerate.
    struct DualBasis {
        Vec3d to_s, to_su, to_sv;
    };
    [[nodiscard]] std::optional<DualBasis> dual_basis() const;
    /// The tile's frustum as five linear forms on w = p − origin, each ≥ 0 at
    /// every point of every ray of the tile: s·(u − u_lo), s·(u_hi − u),
    /// s·(v − v_lo) and s·(v_hi − v) for its rectangle widened by the margin
    /// holds() allows twice over, and s. (Four side planes through the eye
    /// and the eye's plane: together, the tile's rays and nothing behind.)
    struct Planes {
        std::array<Vec3d, 5> forms;
    };
    [[nodiscard]] Planes planes(const DualBasis& basis) const;
    /// True when no ray of the tile meets the box (at any t ≥ 0): the box
    /// lies wholly on the outer side of one of the frustum's planes. False
    /// when that is not certain. (With the tile's planes, when many boxes
    /// are asked.)
    [[nodiscard]] bool misses(const Box3& box) const;
    [[nodiscard]] bool misses(const Box3& box, const Planes& planes) const;
    /// A lower bound on the distance from the segment from a to b (a point
    /// when a = b) to every point of every ray of the tile (t ≥ 0): the
    /// farthest of the planes the whole segment lies beyond, as the rays lie
    /// within each — a little short for rounding; 0 when it may meet them.
    [[nodiscard]] double distance_outside(const Vec3d& a, const Vec3d& b, const Planes& planes) const;
    /// The tile's rectangle [u_lo, u_hi] × [v_lo, v_hi] and a margin far
    /// wider than the rounding of a ray's (u, v).
    struct Rectangle {
        double u_lo, u_hi, v_lo, v_hi;
        [[nodiscard]] double margin() const;
    };
    /// The rectangle widened by the margin misses() allows: the (u, v) of
    /// every ray holds() accepts lie well inside.
    [[nodiscard]] Rectangle widened_rectangle() const;

    /// What holds() asks of a ray, worked out once for the tile: the dual
    /// basis and the rectangle widened by half the margin misses() allows.
    /// Nothing when the three directions are degenerate.
    struct RayCheck {
        DualBasis basis;
        Rectangle accepted;
    };
    [[nodiscard]] std::optional<RayCheck> ray_check() const;
    /// True when the ray is one of the tile's: it leaves the origin,
    /// exactly, through the tile's rectangle of the image plane (within a
    /// margin far narrower than the one misses() allows), so it meets no box
    /// that misses() culls. False when that is not certain.
    [[nodiscard]] bool holds(const Ray& ray, const RayCheck& check) const;

private:
    [[nodiscard]] Rectangle rectangle() const;
    [[nodiscard]] Vec3d depth_form() const {
        const Vec3d n = cross(right, up);
        return n / dot(forward, n);
    }
};

}  // namespace zeroset
