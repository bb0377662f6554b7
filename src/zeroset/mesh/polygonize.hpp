// Polygonizing f within a box: the box is split as an octree, and a cell
// where interval arithmetic proves f ≠ 0 is dropped with everything in it
// (the survey's §6 partitioning; each cell also prunes the tape to what can
// matter there), down to blocks of 4³ grid cells, whose grid points are
// evaluated together. The cells of the grid (resolution³ in all) whose
// corners differ in sign are cut into six tetrahedra each (Kuhn's triangulation, the
// same in every cell) and the surface is marched through them: a vertex
// wherever f changes sign along an edge, placed by regula falsi on that
// edge, shared by every triangle that uses the edge.
//
// What that guarantees: the triangles of neighbouring cells meet along
// shared edges, so a surface that is closed within the box gives a closed
// (watertight), consistently oriented mesh; every vertex lies on a grid edge
// within `vertex_tolerance` of a sign change of f (a point of the surface,
// for continuous f); nothing finer than a cell is resolved — a feature
// thinner than a cell may be missed, and sharp edges are cut, not kept.
#pragma once

#include <cstdint>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/mesh/mesh.hpp"

namespace zeroset {

struct PolygonizeSettings {
    int resolution = 128;  // cells along each side of the box: a power of two, 2 to 4096
    int threads = 0;       // 0: all hardware threads (the mesh is the same for any number)
};

struct PolygonizeStats {
    std::uint64_t cells_visited = 0;   // octree cells whose interval was evaluated
    std::uint64_t leaf_cells = 0;      // finest cells marched (those with corners of both signs)
    double cell_size = 0.0;            // the finest cells' largest side
    double vertex_tolerance = 0.0;     // the widest final bracket of any vertex, in scene units
};

struct PolygonizeResult {
    Mesh mesh;
    PolygonizeStats stats;
};

/// The surface f = 0 within `box`. Throws std::invalid_argument for a
/// resolution that is not a power of two in range or an empty box, and
/// std::domain_error when f is NaN at a point it evaluates (no holes, then).
PolygonizeResult polygonize(const Tape& tape, const Box3& box, const PolygonizeSettings& settings = {});

}  // namespace zeroset
