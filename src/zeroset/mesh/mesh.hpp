// Mesh: a triangle mesh of a surface — shared vertices and triangles of
// vertex indices, counter-clockwise seen from outside (where f > 0).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "zeroset/math/mat4.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct Mesh {
    std::vector<Vec3d> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Moves the mesh by an affine map (an object's placement); a map that
/// mirrors turns the triangles round, so that they still face outwards.
void transform_mesh(Mesh& mesh, const Mat4& map);

}  // namespace zeroset
