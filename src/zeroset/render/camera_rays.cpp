// Pinhole camera basis from from/at/up, the vertical field of view and the
// lens shift.
#include "zeroset/render/camera_rays.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace zeroset {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : eye_(camera.from), width_(width), height_(height) {
    forward_ = normalize(camera.at - camera.from);
    right_ = normalize(cross(camera.up, forward_));  // left-handed screen: +x right, +y up, looking along +z
    up_ = cross(forward_, right_);
    half_height_ = std::tan(camera.fov_degrees * std::numbers::pi / 360.0);
    half_width_ = half_height_ * static_cast<double>(width) / static_cast<double>(height);
    shift_u_ = camera.shift_right * 2.0 * half_height_;
    shift_v_ = camera.shift_up * 2.0 * half_height_;
}

// (The lens shift moves the projections, not their extent.)
double CameraRays::pixel_extent(std::span<const Vec3d> points) const {
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    for (const Vec3d& p : points) {
        const Vec3d v = p - eye_;
        const double depth = dot(v, forward_);
        if (!(depth > 0.0)) return INFINITY;
        const double x = dot(v, right_) / (depth * half_width_) * 0.5 * width_;
        const double y = dot(v, up_) / (depth * half_height_) * 0.5 * height_;
        x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
        y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
    }
    return std::max(x_hi - x_lo, y_hi - y_lo);
}

double CameraRays::footprint_radius() const {
    const double pixel_side = 2.0 * half_height_ / height_;  // on the image plane at distance 1
    // The image's centre lies off the axis by the lens shift, at an angle θ
    // where a pixel subtends pixel_side²·cos³θ.
    const double cos_theta = 1.0 / std::sqrt(1.0 + shift_u_ * shift_u_ + shift_v_ * shift_v_);
    return pixel_side * std::pow(cos_theta, 1.5) / std::sqrt(std::numbers::pi);
}

CameraFrustum CameraRays::frustum(int x0, int y0, int x1, int y1) const {
    CameraFrustum f;
    f.origin = eye_;
    f.forward = forward_;
    f.right = right_;
    f.up = up_;
    // As ray() maps a pixel position to u and v.
    f.u0 = (2.0 * x0 / width_ - 1.0) * half_width_ + shift_u_;
    f.du = 2.0 * half_width_ / width_;
    f.v0 = (1.0 - 2.0 * y0 / height_) * half_height_ + shift_v_;
    f.dv = -2.0 * half_height_ / height_;
    f.columns = x1 - x0;
    f.rows = y1 - y0;
    f.serial = CameraFrustum::new_serial();
    return f;
}

Ray CameraRays::ray(int px, int py, double sx, double sy) const {
    const double u = (2.0 * (px + sx) / width_ - 1.0) * half_width_ + shift_u_;
    const double v = (1.0 - 2.0 * (py + sy) / height_) * half_height_ + shift_v_;
    return {eye_, normalize(forward_ + right_ * u + up_ * v)};
}

}  // namespace zeroset
