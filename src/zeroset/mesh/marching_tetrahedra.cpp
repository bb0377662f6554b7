// TetrahedraMesher (marching_tetrahedra.hpp). Edge vertices are keyed by the
// grid edge, so every cell that meets an edge gets the same vertex.
#include "zeroset/mesh/marching_tetrahedra.hpp"

namespace zeroset {

namespace {

/// Kuhn's six tetrahedra of a cube: each walks from corner 0 to corner 7
/// along the axes in one of the six orders.
constexpr std::array<std::array<int, 4>, 6> tetrahedra = [] {
    std::array<std::array<int, 4>, 6> tets{};
    constexpr int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int t = 0; t < 6; ++t) {
        const int a = 1 << orders[t][0], b = a | (1 << orders[t][1]);
        tets[static_cast<std::size_t>(t)] = {0, a, b, 7};
    }
    return tets;
}();

}  // namespace

TetrahedraMesher::Piece TetrahedraMesher::run(int i, int j, int k, int size) {
    piece_ = Piece{};
    slot_of_edge_.clear();
    walk_.reset_counts();
    walk_.walk(i, j, k, size, [this](const OctreeWalk::Block& block) { march_block(block); });
    piece_.stats.cells_visited = walk_.cells_visited();
    piece_.stats.vertex_tolerance = walk_.vertex_tolerance();
    piece_.nan_at = walk_.nan_at();
    return std::move(piece_);
}

void TetrahedraMesher::march_block(const OctreeWalk::Block& block) {
    for (int c = 0; c < block.size; ++c)
        for (int b = 0; b < block.size; ++b)
            for (int a = 0; a < block.size; ++a) {
                std::array<Vec3d, 8> p;
                std::array<double, 8> f;
                int inside = 0;
                for (int corner = 0; corner < 8; ++corner) {
                    f[corner] = block.value(a + corner_offset(corner, 0), b + corner_offset(corner, 1), c + corner_offset(corner, 2));
                    inside += f[corner] < 0.0 ? 1 : 0;  // f = 0 counts as outside, in every cell alike
                }
                if (inside == 0 || inside == 8) continue;
                ++piece_.stats.leaf_cells;
                const int i = block.i + a, j = block.j + b, k = block.k + c;
                for (int corner = 0; corner < 8; ++corner)
                    p[corner] = walk_.grid_point(i + corner_offset(corner, 0), j + corner_offset(corner, 1), k + corner_offset(corner, 2));
                for (const auto& tet : tetrahedra) march_tetrahedron(tet, i, j, k, p, f);
            }
}

void TetrahedraMesher::march_tetrahedron(const std::array<int, 4>& tet, int i, int j, int k, const std::array<Vec3d, 8>& p,
                                         const std::array<double, 8>& f) {
    std::array<int, 4> in{}, out{};
    int n_in = 0, n_out = 0;
    for (const int c : tet) (f[c] < 0.0 ? in[n_in++] : out[n_out++]) = c;
    if (n_in == 0 || n_out == 0) return;
    Vec3d centre_in{}, centre_out{};
    for (int a = 0; a < n_in; ++a) centre_in += p[in[a]] / static_cast<double>(n_in);
    for (int b = 0; b < n_out; ++b) centre_out += p[out[b]] / static_cast<double>(n_out);
    const Vec3d outward = centre_out - centre_in;
    // A triangle's corner on edge (a, b), and that edge's midpoint: the
    // midpoints never coincide, so they orient the triangle even where its
    // vertices do (f = 0 at a grid point puts them on the corner).
    const auto v = [&](int a, int b) { return Corner{vertex(a, b, i, j, k, p, f), (p[a] + p[b]) * 0.5}; };
    if (n_in == 1 || n_out == 1) {
        const int lone = n_in == 1 ? in[0] : out[0];
        const std::array<int, 4>& others = n_in == 1 ? out : in;
        emit({v(lone, others[0]), v(lone, others[1]), v(lone, others[2])}, outward);
    } else {  // two in, two out: a quad, in cyclic order in0-out0, in0-out1, in1-out1, in1-out0
        const Corner a = v(in[0], out[0]), b = v(in[0], out[1]), c = v(in[1], out[1]), d = v(in[1], out[0]);
        emit({a, b, c}, outward);
        emit({a, c, d}, outward);
    }
}

/// Adds the triangle, turned to face `outward` (towards f > 0).
void TetrahedraMesher::emit(std::array<Corner, 3> t, const Vec3d& outward) {
    const Vec3d n = cross(t[1].midpoint - t[0].midpoint, t[2].midpoint - t[0].midpoint);
    if (dot(n, outward) < 0.0) std::swap(t[1], t[2]);
    const auto& vs = piece_.vertices;
    piece_.triangles.push_back({vs[t[0].slot].first, vs[t[1].slot].first, vs[t[2].slot].first});
}

/// The slot of the vertex on the edge between cell corners a and b (one
/// inside, one outside), made once for every cell that shares the edge.
std::uint32_t TetrahedraMesher::vertex(int a, int b, int i, int j, int k, const std::array<Vec3d, 8>& p,
                                       const std::array<double, 8>& f) {
    // Kuhn's edges join a corner to one whose offsets include its own: key by the lower one.
    const int lower = (a & b) == a ? a : b, upper = lower == a ? b : a;
    const auto n = static_cast<std::uint64_t>(walk_.resolution()) + 1;
    const std::uint64_t index = static_cast<std::uint64_t>(i + corner_offset(lower, 0)) +
                                n * (static_cast<std::uint64_t>(j + corner_offset(lower, 1)) +
                                     n * static_cast<std::uint64_t>(k + corner_offset(lower, 2)));
    const std::uint64_t key = index * 8 + static_cast<std::uint64_t>(upper ^ lower);
    const auto [it, fresh] = slot_of_edge_.try_emplace(key, static_cast<std::uint32_t>(piece_.vertices.size()));
    if (fresh) {
        const int in = f[a] < 0.0 ? a : b, out = in == a ? b : a;
        piece_.vertices.emplace_back(key, walk_.refine(p[in], f[in], p[out], f[out]));
    }
    return it->second;
}

PolygonizeResult TetrahedraMesher::merge(std::vector<Piece>& pieces) {
    PolygonizeResult result;
    std::unordered_map<std::uint64_t, std::uint32_t> index_of_edge;
    for (Piece& piece : pieces) {
        for (const auto& [key, position] : piece.vertices) {
            const auto [it, fresh] = index_of_edge.try_emplace(key, static_cast<std::uint32_t>(result.mesh.vertices.size()));
            if (fresh) result.mesh.vertices.push_back(position);
        }
        for (const auto& t : piece.triangles)
            result.mesh.triangles.push_back({index_of_edge.at(t[0]), index_of_edge.at(t[1]), index_of_edge.at(t[2])});
        PolygonizeStats& s = result.stats;
        s.cells_visited += piece.stats.cells_visited;
        s.leaf_cells += piece.stats.leaf_cells;
        s.vertex_tolerance = std::max(s.vertex_tolerance, piece.stats.vertex_tolerance);
        piece = Piece{};  // its memory back as soon as it is merged
    }
    return result;
}

}  // namespace zeroset
