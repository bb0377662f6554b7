// Marching tetrahedra through the cells the octree walk keeps: every grid
// cell whose corners differ in sign is cut into Kuhn's six tetrahedra (the
// same in every cell) and the surface is marched through them — a vertex
// wherever f changes sign along an edge, placed by regula falsi on that
// edge and shared by every triangle that uses the edge.
//
// What that guarantees: triangles of neighbouring cells meet along shared
// edges, so a surface closed within the box gives a closed, manifold,
// consistently oriented mesh, and every vertex lies on a grid edge within
// the vertex tolerance of a sign change of f. Sharp edges are cut, not kept.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "zeroset/mesh/octree_walk.hpp"
#include "zeroset/mesh/polygonize.hpp"

namespace zeroset {

class TetrahedraMesher {
public:
    /// What one subtree gives: its vertices, keyed by grid edge (in the
    /// order made), and its triangles as triples of those keys.
    struct Piece {
        std::vector<std::pair<std::uint64_t, Vec3d>> vertices;
        std::vector<std::array<std::uint64_t, 3>> triangles;
        PolygonizeStats stats;
        std::optional<Vec3d> nan_at;  // where f was found undefined: the piece stops there
    };

    TetrahedraMesher(const Tape& tape, const Box3& box, int resolution) : walk_(tape, box, resolution) {}

    /// The subtree of `size` grid cells at (i, j, k).
    Piece run(int i, int j, int k, int size);

    /// The pieces' vertices made one (by their edges' keys) and their
    /// triangles renumbered, in the pieces' order: the mesh does not depend
    /// on how the pieces were shared among threads.
    static PolygonizeResult merge(std::vector<Piece>& pieces);

private:
    void march_block(const OctreeWalk::Block& block);
    /// The tetrahedron of these cell corners, positive when
    /// det(v₁ − v₀, v₂ − v₀, v₃ − v₀) > 0.
    void march_tetrahedron(const std::array<int, 4>& corners, bool positive, int i, int j, int k,
                           const std::array<Vec3d, 8>& p, const std::array<double, 8>& f);
    /// Adds the triangle of these vertex slots (in piece_.vertices), as wound.
    void emit(const std::array<std::uint32_t, 3>& slots);
    std::uint32_t vertex(int a, int b, int i, int j, int k, const std::array<Vec3d, 8>& p, const std::array<double, 8>& f);

    OctreeWalk walk_;
    std::unordered_map<std::uint64_t, std::uint32_t> slot_of_edge_;  // this piece's vertices by grid edge
    Piece piece_;
};

}  // namespace zeroset
