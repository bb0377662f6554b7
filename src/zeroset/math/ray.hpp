// Ray: the survey's eq. (4), r(t) = x_o + t·x_d.
#pragma once

#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct Ray {
    Vec3d origin;
    Vec3d dir;

    [[nodiscard]] constexpr Vec3d at(double t) const { return origin + dir * t; }
};

}  // namespace zeroset
