// Polygonizing f within a box: the box is split as an octree, and a cell
// where interval arithmetic proves f ≠ 0 is dropped with everything in it
// (the survey's §6 partitioning; each cell also prunes the tape to what can
// matter there), down to a grid of resolution³ cells. The cells whose
// corners differ in sign are meshed by one of two methods:
//
// - dual contouring (the default; dual_contouring.hpp): a vertex in each
//   cell where the tangent planes of its crossings meet, so sharp corners
//   and edges of the surface are kept; closed and oriented for a surface
//   closed within the box, every vertex within the box and within one cell
//   of a cell the surface crosses;
// - marching tetrahedra (marching_tetrahedra.hpp): vertices on grid edges,
//   on the surface to the reported tolerance; closed, oriented and always
//   manifold, but sharp edges are cut.
//
// Either way nothing finer than a cell is resolved: a feature thinner than
// a cell may be missed. The mesh is the same for any number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <utility>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/mesh/mesh.hpp"

namespace zeroset {

enum class MeshMethod { Dual, Tetrahedra };

/// The methods by name, as the command line and Python spell them.
using NamedMeshMethod = std::pair<std::string_view, MeshMethod>;
inline constexpr std::array<NamedMeshMethod, 2> mesh_methods{{
    {"dual", MeshMethod::Dual},
    {"tetrahedra", MeshMethod::Tetrahedra},
}};

struct PolygonizeSettings {
    int resolution = 128;  // cells along each side of the box: a power of two, 2 to 4096
    int threads = 0;       // 0: all hardware threads (the mesh is the same for any number)
    MeshMethod method = MeshMethod::Dual;
};

struct PolygonizeStats {
    std::uint64_t cells_visited = 0;   // octree cells whose interval was evaluated
    std::uint64_t leaf_cells = 0;      // finest cells meshed (those with corners of both signs)
    double cell_size = 0.0;            // the finest cells' largest side
    /// The widest final bracket of any crossing of the surface on a grid
    /// edge, in scene units: how far the tetrahedra's vertices may be from
    /// the surface, and the dual vertices' planes from their crossings.
    double vertex_tolerance = 0.0;
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
