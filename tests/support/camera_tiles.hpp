// A camera tile for tests of what a tile's rays can meet (misses_tile,
// tile proofs): square, from a point, with +y up.
#pragma once

#include "zeroset/accel/camera_frustum.hpp"

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

}  // namespace zeroset::test
