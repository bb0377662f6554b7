// polygonize: the settings checked, the octree's first levels handed out to
// the threads as subtrees, each meshed by the chosen method, and the pieces
// merged in a fixed order.
#include "zeroset/mesh/polygonize.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "zeroset/mesh/dual_contouring.hpp"
#include "zeroset/mesh/marching_tetrahedra.hpp"

namespace zeroset {

namespace {

constexpr int max_resolution = 4096;

/// The method's pieces of the subtrees below the octree's first levels,
/// meshed on `threads` threads, in an order that does not depend on them.
template <class Mesher>
std::vector<typename Mesher::Piece> mesh_pieces(const Tape& tape, const Box3& box, int resolution, int threads) {
    constexpr int block = OctreeWalk::block;
    const int levels = resolution >= 2 * block ? std::clamp(std::countr_zero(static_cast<unsigned>(resolution / block)), 0, 2) : 0;
    const int size = resolution >> levels, per_side = 1 << levels;
    std::vector<typename Mesher::Piece> pieces(static_cast<std::size_t>(per_side * per_side * per_side));
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        Mesher mesher(tape, box, resolution);
        for (std::size_t n = next++; n < pieces.size(); n = next++) {
            const int a = static_cast<int>(n) % per_side, b = static_cast<int>(n) / per_side % per_side,
                      c = static_cast<int>(n) / (per_side * per_side);
            pieces[n] = mesher.run(a * size, b * size, c * size, size);
        }
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < std::min<int>(threads, static_cast<int>(pieces.size())); ++t) pool.emplace_back(work);
        work();
    }
    for (const auto& piece : pieces)
        if (piece.nan_at) {
            char point[96];
            std::snprintf(point, sizeof point, "(%.6g, %.6g, %.6g)", piece.nan_at->x, piece.nan_at->y, piece.nan_at->z);
            throw std::domain_error(std::string("the surface evaluates to NaN at ") + point +
                                    " — a function outside its domain there (sqrt or log of a negative number, 0/0, "
                                    "…); a mesh needs f defined throughout the box: fix the expression or the box");
        }
    return pieces;
}

}  // namespace

PolygonizeResult polygonize(const Tape& tape, const Box3& box, const PolygonizeSettings& settings) {
    const int r = settings.resolution;
    if (r < 2 || r > max_resolution || !std::has_single_bit(static_cast<unsigned>(r)))
        throw std::invalid_argument("the resolution must be a power of two from 2 to " + std::to_string(max_resolution) +
                                    ", not " + std::to_string(r));
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z) || !std::isfinite(box.diagonal()))
        throw std::invalid_argument("the box to mesh must be finite and not empty");
    const int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    PolygonizeResult result;
    if (settings.method == MeshMethod::Dual) {
        auto pieces = mesh_pieces<DualMesher>(tape, box, r, threads);
        result = DualMesher::merge(pieces, r);
    } else {
        auto pieces = mesh_pieces<TetrahedraMesher>(tape, box, r, threads);
        result = TetrahedraMesher::merge(pieces);
    }
    const Vec3d extent = box.size();
    result.stats.cell_size = std::max({extent.x, extent.y, extent.z}) / r;
    return result;
}

}  // namespace zeroset
