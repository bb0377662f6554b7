// polygonize: the octree walk with pruned tapes, then marching tetrahedra in
// the surviving finest cells. Edge vertices are keyed by the grid edge, so
// every cell that meets an edge gets the same vertex.
#include "zeroset/mesh/polygonize.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdio>
#include <optional>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"

namespace zeroset {

namespace {

constexpr int max_resolution = 4096;
/// The octree stops at blocks of block³ cells: their (block + 1)³ grid
/// points are evaluated at once (shared by neighbouring cells), which is
/// cheaper than an interval evaluation and a pruning for every cell.
constexpr int block = 4;
/// Regula falsi steps on an edge, and the bracket (a fraction of the edge) they aim for.
constexpr int max_refinements = 16;
constexpr double bracket_goal = 1e-7;

/// A corner of a cell: bit 0 is +x, bit 1 +y, bit 2 +z.
constexpr int corner_offset(int corner, int axis) { return (corner >> axis) & 1; }

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

/// What one subtree of the octree gives: its vertices, keyed by grid edge
/// (in the order made), and its triangles as triples of those keys.
struct Piece {
    std::vector<std::pair<std::uint64_t, Vec3d>> vertices;
    std::vector<std::array<std::uint64_t, 3>> triangles;
    PolygonizeStats stats;
    std::optional<Vec3d> nan_at;  // where f was found undefined: the piece stops there
};

/// One thread's octree walk and marching, over the subtrees it is given.
class SubtreeMesher {
public:
    SubtreeMesher(const Tape& tape, const Box3& box, int resolution)
        : full_(tape), box_(box), resolution_(resolution), pruner_(tape), points_(tape),
          tapes_(static_cast<std::size_t>(std::countr_zero(static_cast<unsigned>(resolution))) + 1) {}

    /// The subtree of `size` grid cells at (i, j, k).
    Piece run(int i, int j, int k, int size) {
        piece_ = Piece{};
        slot_of_edge_.clear();
        visit(i, j, k, size, full_, 0);
        return std::move(piece_);
    }

private:
    [[nodiscard]] double coordinate(int index, int axis) const {
        return box_.lo[axis] + (box_.hi[axis] - box_.lo[axis]) * (static_cast<double>(index) / resolution_);
    }
    [[nodiscard]] Vec3d grid_point(int i, int j, int k) const { return {coordinate(i, 0), coordinate(j, 1), coordinate(k, 2)}; }

    /// The octree cell of `size` grid cells at (i, j, k): dropped where f ≠ 0
    /// is proven, split down to blocks, marched there.
    void visit(int i, int j, int k, int size, const Tape& tape, int level) {
        if (piece_.nan_at) return;
        ++piece_.stats.cells_visited;
        const Box3 cell{grid_point(i, j, k), grid_point(i + size, j + size, k + size)};
        const Interval f = pruner_.evaluate(tape, cell);
        if (f.lo > 0.0 || f.hi < 0.0) return;  // no surface here (NaN bounds do not rule it out)
        const Tape& here = pruner_.simplified(tapes_[static_cast<std::size_t>(level)]);
        if (size <= block) {
            march_block(i, j, k, size, here);
            return;
        }
        const int half = size / 2;
        for (int c = 0; c < 8; ++c)
            visit(i + half * corner_offset(c, 0), j + half * corner_offset(c, 1), k + half * corner_offset(c, 2), half,
                  here, level + 1);
    }

    /// The size³ cells from (i, j, k): f at their grid points, then every
    /// cell whose corners differ in sign marched.
    void march_block(int i, int j, int k, int size, const Tape& tape) {
        points_.rebind(tape);
        const int n = size + 1;
        const auto at = [n](int a, int b, int c) { return static_cast<std::size_t>(a + n * (b + n * c)); };
        for (int c = 0; c < n; ++c)
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a) {
                    const Vec3d q = grid_point(i + a, j + b, k + c);
                    const double value = points_(q.x, q.y, q.z);
                    if (std::isnan(value)) {
                        piece_.nan_at = q;
                        return;
                    }
                    block_values_[at(a, b, c)] = value;
                }
        for (int c = 0; c < size; ++c)
            for (int b = 0; b < size; ++b)
                for (int a = 0; a < size; ++a) {
                    std::array<Vec3d, 8> p;
                    std::array<double, 8> f;
                    int inside = 0;
                    for (int corner = 0; corner < 8; ++corner) {
                        f[corner] = block_values_[at(a + corner_offset(corner, 0), b + corner_offset(corner, 1),
                                                     c + corner_offset(corner, 2))];
                        inside += f[corner] < 0.0 ? 1 : 0;  // f = 0 (and NaN) count as outside, in every cell alike
                    }
                    if (inside == 0 || inside == 8) continue;
                    ++piece_.stats.leaf_cells;
                    for (int corner = 0; corner < 8; ++corner)
                        p[corner] = grid_point(i + a + corner_offset(corner, 0), j + b + corner_offset(corner, 1),
                                               k + c + corner_offset(corner, 2));
                    for (const auto& tet : tetrahedra) march_tetrahedron(tet, i + a, j + b, k + c, p, f);
                }
    }

    void march_tetrahedron(const std::array<int, 4>& tet, int i, int j, int k, const std::array<Vec3d, 8>& p,
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
        // midpoints never coincide, so they orient the triangle even where
        // its vertices do (f = 0 at a grid point puts them on the corner).
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

    struct Corner {
        std::uint32_t slot;  // in piece_.vertices
        Vec3d midpoint;      // of its edge
    };

    /// Adds the triangle, turned to face `outward` (towards f > 0).
    void emit(std::array<Corner, 3> t, const Vec3d& outward) {
        const Vec3d n = cross(t[1].midpoint - t[0].midpoint, t[2].midpoint - t[0].midpoint);
        if (dot(n, outward) < 0.0) std::swap(t[1], t[2]);
        const auto& vs = piece_.vertices;
        piece_.triangles.push_back({vs[t[0].slot].first, vs[t[1].slot].first, vs[t[2].slot].first});
    }

    /// The slot of the vertex on the edge between cell corners a and b (one
    /// inside, one outside), made once for every cell that shares the edge.
    std::uint32_t vertex(int a, int b, int i, int j, int k, const std::array<Vec3d, 8>& p, const std::array<double, 8>& f) {
        // Kuhn's edges join a corner to one whose offsets include its own: key by the lower one.
        const int lower = (a & b) == a ? a : b, upper = lower == a ? b : a;
        const auto n = static_cast<std::uint64_t>(resolution_) + 1;
        const std::uint64_t index = static_cast<std::uint64_t>(i + corner_offset(lower, 0)) +
                                    n * (static_cast<std::uint64_t>(j + corner_offset(lower, 1)) +
                                         n * static_cast<std::uint64_t>(k + corner_offset(lower, 2)));
        const std::uint64_t key = index * 8 + static_cast<std::uint64_t>(upper ^ lower);
        const auto [it, fresh] = slot_of_edge_.try_emplace(key, static_cast<std::uint32_t>(piece_.vertices.size()));
        if (fresh) {
            const int in = f[a] < 0.0 ? a : b, out = in == a ? b : a;
            piece_.vertices.emplace_back(key, refine(p[in], f[in], p[out], f[out]));
        }
        return it->second;
    }

    /// Regula falsi (Illinois) on the segment from `in` (f < 0) to `out`
    /// (f ≥ 0): the point of the last bracket's secant.
    Vec3d refine(const Vec3d& in, double f_in, const Vec3d& out, double f_out) {
        if (f_out == 0.0) return out;  // a zero at the corner itself: exact
        double lo = 0.0, hi = 1.0, f_lo = f_in, f_hi = f_out;
        int side = 0;
        for (int step = 0; step < max_refinements && hi - lo > bracket_goal; ++step) {
            const double t = std::clamp(lo + (hi - lo) * f_lo / (f_lo - f_hi), lo, hi);
            if (!std::isfinite(t) || t == lo || t == hi) break;
            const Vec3d q = in + (out - in) * t;
            const double f = points_(q.x, q.y, q.z);
            if (f == 0.0) return q;
            if (std::isnan(f)) {
                piece_.nan_at = q;
                break;
            }
            if (f < 0.0) {
                lo = t, f_lo = f;
                if (side == -1) f_hi *= 0.5;
                side = -1;
            } else {
                hi = t, f_hi = f;
                if (side == 1) f_lo *= 0.5;
                side = 1;
            }
        }
        piece_.stats.vertex_tolerance = std::max(piece_.stats.vertex_tolerance, (hi - lo) * length(out - in));
        const double t = f_lo == f_hi ? 0.5 * (lo + hi) : std::clamp(lo + (hi - lo) * f_lo / (f_lo - f_hi), lo, hi);
        return in + (out - in) * (std::isfinite(t) ? t : 0.5 * (lo + hi));
    }

    const Tape& full_;
    Box3 box_;
    int resolution_;
    TapePruner pruner_;
    Evaluator<double> points_;
    std::vector<Tape> tapes_;  // one pruned tape a level of the octree
    std::array<double, (block + 1) * (block + 1) * (block + 1)> block_values_{};
    std::unordered_map<std::uint64_t, std::uint32_t> slot_of_edge_;  // this piece's vertices by grid edge
    Piece piece_;
};

/// The pieces' vertices made one (by their edges' keys) and their triangles
/// renumbered, in the pieces' order: the mesh does not depend on the threads.
PolygonizeResult merge(std::vector<Piece>& pieces) {
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

}  // namespace

PolygonizeResult polygonize(const Tape& tape, const Box3& box, const PolygonizeSettings& settings) {
    const int r = settings.resolution;
    if (r < 2 || r > max_resolution || !std::has_single_bit(static_cast<unsigned>(r)))
        throw std::invalid_argument("the resolution must be a power of two from 2 to " + std::to_string(max_resolution) +
                                    ", not " + std::to_string(r));
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z) || !std::isfinite(box.diagonal()))
        throw std::invalid_argument("the box to mesh must be finite and not empty");
    // The subtrees below the first levels, handed out to the threads in order.
    const int levels = r >= 2 * block ? std::clamp(std::countr_zero(static_cast<unsigned>(r / block)), 0, 2) : 0;
    const int size = r >> levels, per_side = 1 << levels;
    std::vector<Piece> pieces(static_cast<std::size_t>(per_side * per_side * per_side));
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        SubtreeMesher mesher(tape, box, r);
        for (std::size_t n = next++; n < pieces.size(); n = next++) {
            const int a = static_cast<int>(n) % per_side, b = static_cast<int>(n) / per_side % per_side,
                      c = static_cast<int>(n) / (per_side * per_side);
            pieces[n] = mesher.run(a * size, b * size, c * size, size);
        }
    };
    const int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < std::min<int>(threads, static_cast<int>(pieces.size())); ++t) pool.emplace_back(work);
        work();
    }
    for (const Piece& piece : pieces)
        if (piece.nan_at) {
            char point[96];
            std::snprintf(point, sizeof point, "(%.6g, %.6g, %.6g)", piece.nan_at->x, piece.nan_at->y, piece.nan_at->z);
            throw std::domain_error(std::string("the surface evaluates to NaN at ") + point +
                                    " — a function outside its domain there (sqrt or log of a negative number, 0/0, "
                                    "…); a mesh needs f defined throughout the box: fix the expression or the box");
        }
    PolygonizeResult result = merge(pieces);
    const Vec3d extent = box.size();
    result.stats.cell_size = std::max({extent.x, extent.y, extent.z}) / r;
    return result;
}

}  // namespace zeroset
