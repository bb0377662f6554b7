// CameraRays: the pinhole camera's primary rays — pixel (px, py) plus a
// sub-pixel offset in [0,1)² maps to a unit-direction ray from the eye.
#pragma once

#include "zeroset/math/ray.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

class CameraRays {
public:
    CameraRays(const Camera& camera, int width, int height);

    /// The ray through image position (px + sx, py + sy); y grows downwards.
    [[nodiscard]] Ray ray(int px, int py, double sx, double sy) const;

private:
    Vec3d eye_, forward_, right_, up_;
    double half_height_ = 1.0;  // tan(fov/2)
    double half_width_ = 1.0;
    int width_, height_;
};

}  // namespace zeroset
