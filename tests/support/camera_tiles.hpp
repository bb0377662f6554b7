// Camera tiles for tests of what a tile's rays can meet (misses_tile,
// tile proofs): a square one from a point with +y up, and a tile's rays.
#pragma once

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset::test {

/// A `size` × `size`-pixel camera tile from `origin` looking along
/// `forward`, its pixels `pixel` wide on the image plane, its corner at
/// (u0, v0), with a serial of its own.
inline CameraFrustum square_tile(const Vec3d& origin, const Vec3d& forward, int size, double pixel, double u0,
                                 double v0) {
    CameraFrustum f;
    f.origin = origin;
    f.forward = normalize(forward);
    f.right = normalize(cross(Vec3d{0, 1, 0}, f.forward));
    f.up = cross(f.forward, f.right);
    f.columns = f.rows = size;
    f.du = pixel;
    f.dv = -pixel;
    f.u0 = u0;
    f.v0 = v0;
    f.serial = CameraFrustum::new_serial();
    return f;
}

/// The tile's ray through the point (a, b) of its rectangle, (0, 0) its
/// corner (u0, v0) and (1, 1) the one opposite; its direction not normalised.
inline Ray tile_ray(const CameraFrustum& f, double a, double b) {
    return {f.origin, f.forward + f.right * (f.u0 + a * f.columns * f.du) + f.up * (f.v0 + b * f.rows * f.dv)};
}

}  // namespace zeroset::test
