// Dual contouring through the cells the octree walk keeps (Ju, Losasso,
// Schaefer and Warren 2002, with Nielson's one-vertex-per-patch cells of
// "Dual Marching Cubes", 2004): every grid cell whose corners differ in sign
// gets one vertex for each patch of surface crossing it, placed by the
// quadric error function of its edges' crossings and normals (qef.hpp), so
// corners and edges of the surface are kept; every grid edge where f changes
// sign gives a quad joining the vertices of the four cells around it.
//
// A cell's patches are those of marching cubes (cell_patches.hpp), with the
// same rule in both cells that share a face: so a surface closed within the
// box gives a closed, consistently oriented mesh, and each vertex's triangles
// make one fan. Where the surface wraps round a face in both its cells (a
// handle about a cell thick), the face's rule is flipped, which keeps every
// edge of the mesh to two triangles: a flip never leaves its face wrapped
// nor wraps another (checked over every sign pattern and set of faces, in
// the tests). What it does not guarantee: a vertex lies near the surface,
// not on it — within one cell (vertex_reach) of a cell that the surface
// crosses, and within the box meshed.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "zeroset/mesh/octree_walk.hpp"
#include "zeroset/mesh/polygonize.hpp"

namespace zeroset {

class DualMesher {
public:
    /// A cell with a sign change: its grid key, its first vertex in the
    /// piece, its corners' signs (bit c set where corner c is inside) and
    /// its flipped faces (cell_patches.hpp).
    struct Cell {
        std::uint64_t key;
        std::uint32_t first_vertex;
        std::uint8_t signs, flipped;
    };
    /// What one subtree gives: its cells and their vertices, and its quads,
    /// each a grid edge key (see edge_key) and whether f < 0 at its far end.
    struct Piece {
        std::vector<Cell> cells;
        std::vector<Vec3d> vertices;
        std::vector<std::uint64_t> quads;
        PolygonizeStats stats;
        std::optional<Vec3d> nan_at;
    };

    /// A vertex stays within this many cells of its own cell.
    static constexpr int vertex_reach = 1;

    DualMesher(const Tape& tape, const Box3& box, int resolution);

    /// The subtree of `size` grid cells at (i, j, k).
    Piece run(int i, int j, int k, int size);

    /// The pieces' quads joined to the cells' vertices (by the cells' keys)
    /// and split into triangles, in the pieces' order: the mesh does not
    /// depend on how the pieces were shared among threads.
    static PolygonizeResult merge(std::vector<Piece>& pieces, int resolution);

private:
    struct Crossing {
        Vec3d point;
        Vec3d normal;  // unit, or zero where the gradient is not usable
    };

    void contour_block(const OctreeWalk::Block& block);
    void contour_cell(const OctreeWalk::Block& block, int a, int b, int c, std::uint8_t signs);
    /// The signs of the cell (a, b, c) of the block — or just beyond it.
    int corner_signs(const OctreeWalk::Block& block, int a, int b, int c);
    /// The faces of the cell to flip: those its surface wraps round, as
    /// does the surface of the cell beyond.
    int faces_to_flip(const OctreeWalk::Block& block, int a, int b, int c, int signs);
    /// The crossing on the block's grid edge from (a, b, c) along `axis`,
    /// found once per block.
    const Crossing& crossing(const OctreeWalk::Block& block, int a, int b, int c, int axis);

    OctreeWalk walk_;
    Evaluator<Dual<double>> gradients_;
    static constexpr int block_edges = 3 * OctreeWalk::block_points * OctreeWalk::block_points * OctreeWalk::block_points;
    std::array<Crossing, block_edges> crossings_{};
    std::array<std::uint32_t, block_edges> crossing_stamp_{};  // == block_stamp_ where crossings_ is of this block
    std::uint32_t block_stamp_ = 0;
    Piece piece_;
};

}  // namespace zeroset
