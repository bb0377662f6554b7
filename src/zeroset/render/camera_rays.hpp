// CameraRays: the pinhole camera's primary rays — pixel (px, py) plus a
// sub-pixel offset in [0,1)² maps to a unit-direction ray from the eye.
#pragma once

#include <span>

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/math/ray.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

class CameraRays {
public:
    CameraRays(const Camera& camera, int width, int height);

    /// The ray through image position (px + sx, py + sy); y grows downwards.
    [[nodiscard]] Ray ray(int px, int py, double sx, double sy) const;
    /// The rays of pixels [x0, x1) × [y0, y1), every sub-pixel offset.
    [[nodiscard]] CameraFrustum frustum(int x0, int y0, int x1, int y1) const;
    /// The radius, per unit of distance along a ray, of the disk as large as
    /// one pixel (its area) at the image's centre: the footprint cone
    /// tracing widens a ray to (render/cone_tracer.hpp).
    [[nodiscard]] double footprint_radius() const;
    /// The larger side, in pixels, of the rectangle the points project to
    /// (beyond the image too); +∞ when one is not in front of the eye.
    [[nodiscard]] double pixel_extent(std::span<const Vec3d> points) const;

private:
    Vec3d eye_, forward_, right_, up_;
    double half_height_ = 1.0;  // tan(fov/2)
    double half_width_ = 1.0;
    double shift_u_ = 0.0, shift_v_ = 0.0;  // the image's centre on the plane at distance 1 (Camera::shift_right, shift_up)
    int width_, height_;
};

}  // namespace zeroset
