// The camera's rays: a shifted lens moves the image's centre off the view
// axis, and a tile's frustum covers the rays the tile traces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "zeroset/render/camera_rays.hpp"

namespace zeroset {
namespace {

TEST(CameraRays, AShiftedLensMovesTheImagesCentreOffTheAxis) {
    Camera camera;  // from (0, 0, −5) towards the origin, +y up
    camera.fov_degrees = 60.0;
    camera.shift_up = 0.1;
    camera.shift_right = -0.05;
    const CameraRays rays(camera, 200, 100);
    // The centre of the image looks along (0, 0, 1) + its shift on the plane
    // at distance 1, where the image is 2·tan 30° high.
    const double height = 2.0 * std::tan(std::numbers::pi / 6.0);
    const Ray centre = rays.ray(100, 50, 0.0, 0.0);
    const Vec3d expected = normalize(Vec3d{-0.05 * height, 0.1 * height, 1.0});
    EXPECT_NEAR(length(centre.dir - expected), 0.0, 1e-12);
    // The verticals stay parallel: the image plane still faces the axis, so a
    // column's rays share their right component per unit of depth.
    const Ray top = rays.ray(30, 0, 0.5, 0.5), bottom = rays.ray(30, 99, 0.5, 0.5);
    EXPECT_NEAR(top.dir.x / top.dir.z, bottom.dir.x / bottom.dir.z, 1e-12);
}

TEST(CameraRays, AShiftedImagesCentrePixelIsSmallerSeenFromTheEye) {
    Camera camera;
    camera.fov_degrees = 60.0;
    const double on_axis = CameraRays(camera, 100, 100).footprint_radius();
    camera.shift_up = 1.0;  // the centre 49° off the axis: a pixel there subtends cos³θ as much
    const double cos_theta = 1.0 / std::hypot(1.0, 2.0 * std::tan(std::numbers::pi / 6.0));
    EXPECT_NEAR(CameraRays(camera, 100, 100).footprint_radius() / on_axis, std::pow(cos_theta, 1.5), 1e-12);
}

TEST(CameraRays, ATilesFrustumHoldsItsShiftedRays) {
    Camera camera;
    camera.shift_up = 0.3;
    camera.shift_right = 0.2;
    const CameraRays rays(camera, 64, 48);
    const CameraFrustum tile = rays.frustum(16, 8, 32, 24);
    for (const auto& [px, py, sx, sy] : {std::array<double, 4>{16, 8, 0, 0}, {31, 23, 1, 1}, {20, 10, 0.5, 0.25}}) {
        const Ray r = rays.ray(static_cast<int>(px), static_cast<int>(py), sx, sy);
        const double u = tile.u0 + (px - 16 + sx) * tile.du, v = tile.v0 + (py - 8 + sy) * tile.dv;
        const Vec3d through = tile.at(1.0, u, v) - tile.origin;
        EXPECT_NEAR(length(normalize(through) - r.dir), 0.0, 1e-12) << px << ", " << py;
    }
}

}  // namespace
}  // namespace zeroset
