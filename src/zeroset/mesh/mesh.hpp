// Mesh: a triangle mesh of a surface — shared vertices and triangles of
// vertex indices, counter-clockwise seen from outside (where f > 0).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct Mesh {
    std::vector<Vec3d> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace zeroset
