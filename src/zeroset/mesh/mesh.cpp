// transform_mesh (mesh.hpp).
#include "zeroset/mesh/mesh.hpp"

#include <utility>

namespace zeroset {

void transform_mesh(Mesh& mesh, const Mat4& map) {
    if (map.is_identity()) return;
    for (Vec3d& v : mesh.vertices) v = map.transform_point(v);
    const double handedness =
        dot(cross(map.transform_vector({1, 0, 0}), map.transform_vector({0, 1, 0})), map.transform_vector({0, 0, 1}));
    if (handedness < 0.0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace zeroset
