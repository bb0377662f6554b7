// Pinhole camera basis from from/at/up and the vertical field of view.
#include "zeroset/render/camera_rays.hpp"

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
}

Ray CameraRays::ray(int px, int py, double sx, double sy) const {
    const double u = (2.0 * (px + sx) / width_ - 1.0) * half_width_;
    const double v = (1.0 - 2.0 * (py + sy) / height_) * half_height_;
    return {eye_, normalize(forward_ + right_ * u + up_ * v)};
}

}  // namespace zeroset
