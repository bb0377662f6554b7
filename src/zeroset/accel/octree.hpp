// Octree: spatial partitioning of one implicit primitive's bounds (survey
// §6.2–6.3), so that rays run their method only in the cells that may hold
// the surface, each with the tape pruned to it (expr/tape_pruner.hpp) —
// fewer clauses and tighter enclosures, hence a smaller Lipschitz bound L.
//
// Two rules decide which cells survive, one per partitioning of the survey:
//  - Lipschitz (Kalra and Barr, §6.3, Fig. 13): a cell is discarded when the
//    interval of f over it excludes 0, or when |f(centre)| > L·r with L the
//    cell's own Lipschitz bound and r its half-diagonal; a cell whose
//    corners differ in sign is kept without those tests. Sound: no surface
//    point is ever in a discarded cell.
//  - VertexSign (Bloomenthal's octree, §6.3): a cell is kept only when its
//    corners differ in sign (after two levels of uniform subdivision).
//    Cheap, but it loses thin features that pass between the corners — the
//    survey's "main flaw", kept as the alternative for comparison.
//  - SeedFill (Bloomenthal's surface tracking, §6.2): the cells of the
//    finest grid whose corners differ in sign, found by a 3-D seed fill
//    from a seed cell over face neighbours. It keeps only the part of the
//    surface connected to its seed, loses what the corners miss (thin
//    features, caps bulging into a cell), and past the cell cap the rest.
// Surviving cells are subdivided to `max_depth`; the leaves are the cells.
// Every cell is built over its box widened by a pad of 10⁻⁵ of the root's
// diagonal (at least 64 ulps of its coordinates), and rays walk the boxes
// widened by a tenth of that: rounding in the slab test never loses a root
// on a face between two cells, and the methods' probes just past the end of
// a cell's span (sphere tracing looks 2ε = 2·10⁻⁶ of the object's size
// ahead; pole probes 16 tangent widths) stay where the cell's tape holds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset {

enum class Partition : std::uint8_t {
    Auto,       // Lipschitz for tapes of at least `partition_min_clauses` clauses, else None
    None,       // the method runs over the whole bounds
    Lipschitz,  // Kalra–Barr
    VertexSign,  // Bloomenthal's octree
    SeedFill     // Bloomenthal's surface tracking
};

std::string_view partition_name(Partition partition);
std::optional<Partition> partition_from_name(std::string_view name);
/// Every partition, in the order of the enum.
std::span<const Partition> all_partitions();

struct OctreeSettings {
    Partition rule = Partition::Lipschitz;  // Lipschitz, VertexSign or SeedFill
    int max_depth = 6;
    /// Memory caps: cells (leaves) stop subdividing once this many exist,
    /// and pruned tapes stop being stored once they hold this many clauses
    /// in all (cells then walk a coarser ancestor's tape, still valid).
    std::size_t max_cells = std::size_t{1} << 18;
    std::size_t max_stored_clauses = std::size_t{1} << 22;
    int threads = 0;  // 0: all cores
    /// Called with (subtrees built, subtrees in all) as a subdividing build
    /// goes, from one thread at a time; may be empty.
    std::function<void(int, int)> on_progress;
};

/// The statistics' Lipschitz bounds are computed for one cell in this many.
inline constexpr std::size_t lipschitz_sample = 8;

/// A surviving leaf cell.
struct OctreeCell {
    static constexpr std::uint32_t full_tape = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t tape = full_tape;  // index into Octree::tapes(), or the source tape
    bool can_prune = false;          // its tape still has a min or max
    /// L over the cell, rounded up (+∞ if unbounded), for one cell in
    /// `lipschitz_sample`; NaN for the others.
    float lipschitz = std::numeric_limits<float>::quiet_NaN();
};

struct OctreeStats {
    std::size_t cells = 0;           // surviving leaves
    std::size_t nodes = 0;           // all nodes, empty ones included
    std::size_t stored_clauses = 0;  // clauses in all stored tapes
    std::size_t bytes = 0;           // nodes, cells and stored tapes
    std::size_t full_clauses = 0;    // the source tape's
    double mean_cell_clauses = 0;    // over the cells
    double median_lipschitz = 0;     // over the sampled cells with finite L
    double p90_lipschitz = 0;
    std::size_t unbounded_cells = 0;  // sampled cells with L = ∞
    double build_seconds = 0;
    int depth = 0;
};

class Octree {
public:
    /// Builds the octree of f = `tape` over `box`, in parallel.
    Octree(const Tape& tape, const Box3& box, const OctreeSettings& settings);
    // Cells may walk `tape` itself, held by pointer.
    Octree(const Octree&) = delete;
    Octree& operator=(const Octree&) = delete;

    /// Calls visit(span, cell) for every cell the ray passes through within
    /// `span`, front to back, with the part of the span inside the cell,
    /// until visit returns true.
    template <class Visit>
    void walk(const Ray& ray, Span span, Visit&& visit) const;

    [[nodiscard]] const Tape& tape_of(const OctreeCell& cell) const {
        return cell.tape == OctreeCell::full_tape ? *source_ : tapes_[cell.tape];
    }
    [[nodiscard]] const OctreeStats& stats() const { return stats_; }
    [[nodiscard]] const std::vector<OctreeCell>& cells() const { return cells_; }
    /// The boxes of the cells, in the order of cells() (for tests and plots).
    [[nodiscard]] const std::vector<Box3>& cell_boxes() const { return boxes_; }

private:
    friend class OctreeBuilder;
    enum class Kind : std::uint8_t { Empty, Leaf, Inner };
    struct Node {
        Kind kind = Kind::Empty;
        std::uint32_t index = 0;  // Leaf: the cell; Inner: the first of its 8 children
    };
    static constexpr int max_supported_depth = 12;

    /// Child `i` of `box` (bit 0: upper x half, bit 1: y, bit 2: z).
    static Box3 child_box(const Box3& box, int i) {
        const Vec3d mid = box.center();
        Box3 child = box;
        for (int axis = 0; axis < 3; ++axis) ((i >> axis) & 1 ? child.lo : child.hi)[axis] = mid[axis];
        return child;
    }
    void build_by_subdivision(const OctreeSettings& settings);
    /// Bloomenthal's surface tracking (octree_seed_fill.cpp).
    void build_by_seed_fill(const OctreeSettings& settings);
    void finish_stats(const OctreeSettings& settings, double build_seconds);
    [[nodiscard]] static Box3 padded(const Box3& box, double pad) {
        return {box.lo - Vec3d{pad, pad, pad}, box.hi + Vec3d{pad, pad, pad}};
    }

    const Tape* source_;
    Box3 root_;
    double pad_ = 0.0;
    std::vector<Node> nodes_;
    std::vector<OctreeCell> cells_;
    std::vector<Tape> tapes_;
    std::vector<Box3> boxes_;
    OctreeStats stats_;
};

template <class Visit>
void Octree::walk(const Ray& ray, Span span, Visit&& visit) const {
    if (nodes_.empty() || !(span.t0 <= span.t1)) return;
    // Children in the order i ^ mask are front to back along the ray: a
    // child the ray reaches later differs from an earlier one only in the
    // bits of the axes it travels along.
    const int mask = (ray.dir.x < 0.0 ? 1 : 0) | (ray.dir.y < 0.0 ? 2 : 0) | (ray.dir.z < 0.0 ? 4 : 0);
    struct Entry {
        std::uint32_t node;
        Box3 box;
    };
    Entry stack[7 * max_supported_depth + 1];
    int top = 0;
    stack[top++] = {0, root_};
    const double pad = 0.1 * pad_;
    while (top > 0) {
        const Entry e = stack[--top];
        const Node& node = nodes_[e.node];
        if (node.kind == Kind::Empty) continue;
        const auto inside = padded(e.box, pad).clip(ray, span.t0, span.t1);
        if (!inside) continue;
        if (node.kind == Kind::Leaf) {
            if (visit(*inside, cells_[node.index])) return;
            continue;
        }
        for (int i = 7; i >= 0; --i) {
            const int child = i ^ mask;
            if (nodes_[node.index + child].kind != Kind::Empty)
                stack[top++] = {node.index + static_cast<std::uint32_t>(child), child_box(e.box, child)};
        }
    }
}

}  // namespace zeroset
