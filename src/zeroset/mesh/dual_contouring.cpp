// DualMesher (dual_contouring.hpp): the vertices of a block's cells, the
// faces flipped to keep the mesh manifold, and the quads joined up across
// pieces.
#include "zeroset/mesh/dual_contouring.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "zeroset/mesh/cell_patches.hpp"
#include "zeroset/mesh/qef.hpp"

namespace zeroset {

namespace {

std::uint64_t point_key(std::int64_t i, std::int64_t j, std::int64_t k, int resolution) {
    const auto n = static_cast<std::uint64_t>(resolution) + 1;
    return static_cast<std::uint64_t>(i) + n * (static_cast<std::uint64_t>(j) + n * static_cast<std::uint64_t>(k));
}

/// Removes the vertices no triangle uses — those of cells at the box's
/// boundary whose quads the box cut — keeping the others' order.
void drop_unused_vertices(Mesh& mesh) {
    constexpr auto unused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> index(mesh.vertices.size(), unused);
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t) index[v] = 0;
    std::uint32_t kept = 0;
    for (std::size_t v = 0; v < index.size(); ++v)
        if (index[v] == 0) {
            index[v] = kept;
            mesh.vertices[kept++] = mesh.vertices[v];
        }
    mesh.vertices.resize(kept);
    for (auto& t : mesh.triangles)
        for (std::uint32_t& v : t) v = index[v];
}

}  // namespace

DualMesher::DualMesher(const Tape& tape, const Box3& box, int resolution)
    : walk_(tape, box, resolution), gradients_(tape) {}

DualMesher::Piece DualMesher::run(int i, int j, int k, int size) {
    piece_ = Piece{};
    walk_.walk(i, j, k, size, [this](const OctreeWalk::Block& block) { contour_block(block); });
    walk_.report(piece_);
    return std::move(piece_);
}

void DualMesher::contour_block(const OctreeWalk::Block& block) {
    gradients_.rebind(*block.tape);
    ++block_stamp_;
    for (int c = 0; c < block.size; ++c)
        for (int b = 0; b < block.size; ++b)
            for (int a = 0; a < block.size; ++a) {
                const int signs = corner_signs(block, a, b, c);
                if (signs == 0 || signs == 255) continue;
                contour_cell(block, a, b, c, static_cast<std::uint8_t>(signs));
                if (walk_.nan_at()) return;
            }
}

int DualMesher::corner_signs(const OctreeWalk::Block& block, int a, int b, int c) {
    int signs = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const int p = a + corner_offset(corner, 0), q = b + corner_offset(corner, 1), r = c + corner_offset(corner, 2);
        double f;
        if (std::min({p, q, r}) >= 0 && std::max({p, q, r}) <= block.size) {
            f = block.value(p, q, r);
        } else {  // beyond the block, where its pruned tape need not hold: the full tape, the same value or NaN
            f = walk_.grid_value(block.i + p, block.j + q, block.k + r);
        }
        signs |= f < 0.0 ? 1 << corner : 0;  // f = 0 counts as outside, in every cell alike
    }
    return signs;
}

int DualMesher::faces_to_flip(const OctreeWalk::Block& block, int a, int b, int c, int signs) {
    const cell::Patches& plain = cell::unflipped[static_cast<std::size_t>(signs)];
    int flipped = 0;
    for (int face = 0; face < 6; ++face) {
        if (!cell::wraps_round(plain, signs, face)) continue;
        int beyond[3] = {a, b, c};
        beyond[face / 2] += face % 2 == 1 ? 1 : -1;
        const int global = (face / 2 == 0 ? block.i : face / 2 == 1 ? block.j : block.k) + beyond[face / 2];
        if (global < 0 || global >= walk_.resolution()) continue;  // no cell beyond: the box cuts the surface here
        const int other = corner_signs(block, beyond[0], beyond[1], beyond[2]);
        if (cell::wraps_round(cell::unflipped[static_cast<std::size_t>(other)], other, cell::opposite_face(face)))
            flipped |= 1 << face;
    }
    return flipped;
}

void DualMesher::contour_cell(const OctreeWalk::Block& block, int a, int b, int c, std::uint8_t signs) {
    ++piece_.stats.leaf_cells;
    const int cell[3] = {block.i + a, block.j + b, block.k + c};
    const int flipped = faces_to_flip(block, a, b, c, signs);
    const cell::Patches patches = cell::patches_of_cell(signs, flipped);
    std::array<Qef, 4> qefs;
    for (int e = 0; e < 12; ++e) {
        const int patch = patches.of_edge[static_cast<std::size_t>(e)];
        if (patch < 0) continue;
        const int low = cell::edge_low_corner(e);
        const Crossing& x = crossing(block, a + corner_offset(low, 0), b + corner_offset(low, 1), c + corner_offset(low, 2),
                                     cell::edge_axis(e));
        qefs[static_cast<std::size_t>(patch)].add(x.point, x.normal);
    }
    // A sharp corner can poke into a neighbouring cell without reaching any
    // of its grid points, and so show only in this cell's planes: the vertex
    // may go as far as the neighbours, to keep it.
    // Never past the box meshed, though.
    const auto low = [&](int axis) { return std::max(cell[axis] - vertex_reach, 0); };
    const auto high = [&](int axis) { return std::min(cell[axis] + 1 + vertex_reach, walk_.resolution()); };
    const Box3 box{walk_.grid_point(low(0), low(1), low(2)), walk_.grid_point(high(0), high(1), high(2))};
    piece_.cells.push_back({point_key(cell[0], cell[1], cell[2], walk_.resolution()),
                            static_cast<std::uint32_t>(piece_.vertices.size()), signs, static_cast<std::uint8_t>(flipped)});
    for (int p = 0; p < patches.count; ++p) piece_.vertices.push_back(qefs[static_cast<std::size_t>(p)].solve(box));
    // The quads of the edges leaving the cell's low corner: this cell is the
    // one of their four that lies beyond them on both other axes.
    for (int axis = 0; axis < 3; ++axis) {
        if (!cell::crosses(signs, axis * 4)) continue;
        if (cell[(axis + 1) % 3] == 0 || cell[(axis + 2) % 3] == 0) continue;  // the box cuts the surface here
        const std::uint64_t edge = point_key(cell[0], cell[1], cell[2], walk_.resolution()) * 3 + static_cast<std::uint64_t>(axis);
        piece_.quads.push_back(edge * 2 + (cell::inside(signs, 1 << axis) ? 1 : 0));
    }
}

const DualMesher::Crossing& DualMesher::crossing(const OctreeWalk::Block& block, int a, int b, int c, int axis) {
    constexpr int n = OctreeWalk::block_points;
    const auto slot = static_cast<std::size_t>(axis + 3 * (a + n * (b + n * c)));
    Crossing& x = crossings_[slot];
    if (crossing_stamp_[slot] == block_stamp_) return x;
    crossing_stamp_[slot] = block_stamp_;
    const int d[3] = {axis == 0, axis == 1, axis == 2};
    const double f0 = block.value(a, b, c), f1 = block.value(a + d[0], b + d[1], c + d[2]);
    const Vec3d p0 = walk_.grid_point(block.i + a, block.j + b, block.k + c);
    const Vec3d p1 = walk_.grid_point(block.i + a + d[0], block.j + b + d[1], block.k + c + d[2]);
    x.point = f0 < 0.0 ? walk_.refine(p0, f0, p1, f1) : walk_.refine(p1, f1, p0, f0);
    const Vec3d g = evaluate_gradient(gradients_, x.point).g;
    const double norm = length(g);
    x.normal = norm > 0.0 && std::isfinite(norm) ? g / norm : Vec3d{};
    return x;
}

PolygonizeResult DualMesher::merge(std::vector<Piece>& pieces, int resolution) {
    struct Found {
        std::uint32_t first_vertex;
        std::uint8_t signs, flipped;
    };
    PolygonizeResult result;
    std::unordered_map<std::uint64_t, Found> cells;
    std::size_t cell_count = 0;
    for (const Piece& piece : pieces) cell_count += piece.cells.size();
    cells.reserve(cell_count);
    for (const Piece& piece : pieces) {
        const auto offset = static_cast<std::uint32_t>(result.mesh.vertices.size());
        for (const Cell& cell : piece.cells) cells.emplace(cell.key, Found{offset + cell.first_vertex, cell.signs, cell.flipped});
        result.mesh.vertices.insert(result.mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    }
    const std::int64_t n = resolution + 1;
    for (Piece& piece : pieces) {
        for (const std::uint64_t quad : piece.quads) {
            const bool far_inside = (quad & 1) != 0;
            const int axis = static_cast<int>(quad / 2 % 3);
            const auto point = static_cast<std::int64_t>(quad / 6);
            const std::int64_t at[3] = {point % n, point / n % n, point / (n * n)};
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            // The four cells around the edge, counter-clockwise about +axis.
            std::array<std::uint32_t, 4> ring{};
            constexpr int around[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int q = 0; q < 4; ++q) {
                std::int64_t c[3] = {at[0], at[1], at[2]};
                c[u] -= 1 - around[q][0];
                c[v] -= 1 - around[q][1];
                const auto found = cells.find(point_key(c[0], c[1], c[2], resolution));
                if (found == cells.end())
                    throw std::logic_error("dual contouring: a cell beside a crossing was not contoured");
                const int e = axis * 4 + (1 - around[q][0]) + 2 * (1 - around[q][1]);
                const int patch = cell::patches_of_cell(found->second.signs, found->second.flipped).of_edge[static_cast<std::size_t>(e)];
                if (patch < 0) throw std::logic_error("dual contouring: neighbouring cells disagree on a crossing");
                ring[static_cast<std::size_t>(q)] = found->second.first_vertex + static_cast<std::uint32_t>(patch);
            }
            if (far_inside) std::swap(ring[1], ring[3]);  // the outside is towards −axis: turn the quad round
            // Split along the diagonal whose two triangles bend least.
            const std::vector<Vec3d>& p = result.mesh.vertices;
            const auto bend = [&](int d) {
                const Vec3d& a = p[ring[static_cast<std::size_t>(d)]];
                const Vec3d n1 = cross(p[ring[static_cast<std::size_t>(d + 1)]] - a, p[ring[static_cast<std::size_t>((d + 2) % 4)]] - a);
                const Vec3d& b = p[ring[static_cast<std::size_t>((d + 2) % 4)]];
                const Vec3d n2 = cross(p[ring[static_cast<std::size_t>((d + 3) % 4)]] - b, a - b);
                const double l = length(n1) * length(n2);
                return l > 0.0 ? dot(n1, n2) / l : -2.0;
            };
            const int d = bend(0) >= bend(1) ? 0 : 1;
            const auto r = [&](int q) { return ring[static_cast<std::size_t>((d + q) % 4)]; };
            result.mesh.triangles.push_back({r(0), r(1), r(2)});
            result.mesh.triangles.push_back({r(0), r(2), r(3)});
        }
        PolygonizeStats& s = result.stats;
        s.cells_visited += piece.stats.cells_visited;
        s.leaf_cells += piece.stats.leaf_cells;
        s.vertex_tolerance = std::max(s.vertex_tolerance, piece.stats.vertex_tolerance);
        piece = Piece{};
    }
    drop_unused_vertices(result.mesh);
    return result;
}

}  // namespace zeroset
