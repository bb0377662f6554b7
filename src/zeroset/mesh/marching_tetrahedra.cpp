// TetrahedraMesher (marching_tetrahedra.hpp). Edge vertices are keyed by the
// grid edge, so every cell that meets an edge gets the same vertex.
#include "zeroset/mesh/marching_tetrahedra.hpp"

namespace zeroset {

namespace {

/// Kuhn's six tetrahedra of a cube: each walks from corner 0 to corner 7
/// along the axes in one of the six orders. Its orientation, the sign of
/// det(v₁ − v₀, v₂ − v₀, v₃ − v₀) = det(e_a, e_b, e_c) for the order (a, b, c),
/// is that order's parity.
struct Tetrahedron {
    std::array<int, 4> corners;
    bool positive;
};
constexpr std::array<Tetrahedron, 6> tetrahedra = [] {
    std::array<Tetrahedron, 6> tets{};
    constexpr int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int t = 0; t < 6; ++t) {
        const int a = 1 << orders[t][0], b = a | (1 << orders[t][1]);
        const bool even = orders[t][0] < orders[t][1] ? orders[t][1] < orders[t][2] || orders[t][2] < orders[t][0]
                                                      : orders[t][1] < orders[t][2] && orders[t][2] < orders[t][0];
        tets[static_cast<std::size_t>(t)] = {{0, a, b, 7}, even};
    }
    return tets;
}();

/// Whether (p[0], p[1], p[2], p[3]), a permutation of 0 to 3, is even.
constexpr bool even_permutation(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += p[static_cast<std::size_t>(i)] > p[static_cast<std::size_t>(j)] ? 1 : 0;
    return inversions % 2 == 0;
}

}  // namespace

TetrahedraMesher::Piece TetrahedraMesher::run(int i, int j, int k, int size) {
    piece_ = Piece{};
    slot_of_edge_.clear();
    walk_.walk(i, j, k, size, [this](const OctreeWalk::Block& block) { march_block(block); });
    walk_.report(piece_);
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
                for (const Tetrahedron& tet : tetrahedra) march_tetrahedron(tet.corners, tet.positive, i, j, k, p, f);
            }
}

// The triangles' winding comes from the tetrahedron's orientation and the
// order of its corners, never from positions (which may coincide, or be too
// close for a cross product): in a positive tetrahedron (v₀, v₁, v₂, v₃), the
// face (v_j, v_k, v_l) opposite v_i faces away from it when (i, j, k, l) is
// an even permutation. A lone inside corner's triangle is parallel to its
// opposite face and must face away from it; a lone outside corner's must
// face towards it; the quad of two in, two out, in order in₀out₀, in₀out₁,
// in₁out₁, faces from the inside edge to the outside one when
// (in₀, in₁, out₀, out₁) is even.
void TetrahedraMesher::march_tetrahedron(const std::array<int, 4>& corners, bool positive, int i, int j, int k,
                                         const std::array<Vec3d, 8>& p, const std::array<double, 8>& f) {
    std::array<int, 4> in{}, out{};  // positions 0 to 3 in the tetrahedron
    int n_in = 0, n_out = 0;
    for (int v = 0; v < 4; ++v) (f[corners[static_cast<std::size_t>(v)]] < 0.0 ? in[n_in++] : out[n_out++]) = v;
    if (n_in == 0 || n_out == 0) return;
    const auto v = [&](int a, int b) {
        return vertex(corners[static_cast<std::size_t>(a)], corners[static_cast<std::size_t>(b)], i, j, k, p, f);
    };
    if (n_in == 1 || n_out == 1) {
        const int lone = n_in == 1 ? in[0] : out[0];
        const std::array<int, 4>& others = n_in == 1 ? out : in;
        const bool away = even_permutation({lone, others[0], others[1], others[2]}) == positive;
        // Away from the lone corner for an inside one, towards it for an outside one.
        std::array<std::uint32_t, 3> t{v(lone, others[0]), v(lone, others[1]), v(lone, others[2])};
        if (away != (n_in == 1)) std::swap(t[1], t[2]);
        emit(t);
    } else {
        std::array<std::uint32_t, 4> q{v(in[0], out[0]), v(in[0], out[1]), v(in[1], out[1]), v(in[1], out[0])};
        if (even_permutation({in[0], in[1], out[0], out[1]}) != positive) std::swap(q[1], q[3]);
        emit({q[0], q[1], q[2]});
        emit({q[0], q[2], q[3]});
    }
}

void TetrahedraMesher::emit(const std::array<std::uint32_t, 3>& slots) {
    const auto& vs = piece_.vertices;
    piece_.triangles.push_back({vs[slots[0]].first, vs[slots[1]].first, vs[slots[2]].first});
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
