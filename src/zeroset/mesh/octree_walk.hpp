// OctreeWalk: the part of polygonizing that every meshing method shares.
// The box is split as an octree; a cell where interval arithmetic proves
// f ≠ 0 is dropped with everything in it (the survey's §6 partitioning;
// each cell also prunes the tape to what can matter there), down to blocks
// of block³ grid cells, whose (block + 1)³ grid points are evaluated
// together and handed to the method. The method finds sign changes on grid
// edges with refine(), on the block's pruned tape.
//
// Every block that contains a grid edge where f changes sign is visited: the
// edge lies in every octree cell above it, whose interval therefore holds
// both signs. Grid points get the same value in every block (a pruned tape
// only drops min/max branches that lose throughout its cell), so
// neighbouring blocks agree on every sign — except where a dropped branch
// is NaN (interval sqrt and log keep to their domain, so a branch can lose
// over a cell where the full tape is undefined): the full tape says NaN
// there, and grid_value() reports it. Grid points are evaluated in the batch
// evaluator's SIMD lanes, a block at a time; the steps along edges one by
// one (their signs are the grid's, so the two evaluators need not agree to
// the bit).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {

/// A corner of a cell: bit 0 is +x, bit 1 +y, bit 2 +z.
constexpr int corner_offset(int corner, int axis) { return (corner >> axis) & 1; }

class OctreeWalk {
public:
    /// The octree stops at blocks of block³ cells: their grid points are
    /// evaluated at once (shared by neighbouring cells), which is cheaper
    /// than an interval evaluation and a pruning for every cell.
    static constexpr int block = 4;
    static constexpr int block_points = block + 1;

    /// The grid points of one block, and the tape pruned to it.
    struct Block {
        int i, j, k, size;  // its first cell and its cells a side
        const Tape* tape;
        const std::array<double, block_points * block_points * block_points>* values;
        /// f at the grid point (i + a, j + b, k + c), 0 ≤ a, b, c ≤ size.
        [[nodiscard]] double value(int a, int b, int c) const {
            return (*values)[static_cast<std::size_t>(a + block_points * (b + block_points * c))];
        }
    };

    OctreeWalk(const Tape& tape, const Box3& box, int resolution)
        : full_(tape), box_(box), resolution_(resolution), pruner_(tape), points_(tape), grid_(tape), full_grid_(tape),
          tapes_(static_cast<std::size_t>(std::countr_zero(static_cast<unsigned>(resolution))) + 1) {}

    /// Walks the subtree of `size` grid cells at (i, j, k) and calls
    /// on_block(const Block&) for each block that may hold the surface, in a
    /// fixed order; the counts start afresh. Stops early where f is NaN (see
    /// nan_at()).
    template <class OnBlock>
    void walk(int i, int j, int k, int size, OnBlock&& on_block) {
        nan_at_.reset();
        cells_visited_ = 0;
        vertex_tolerance_ = 0.0;
        visit(i, j, k, size, full_, 0, on_block);
    }

    /// The last walk's counts, and where it found f undefined, into a
    /// method's piece.
    template <class Piece>
    void report(Piece& piece) const {
        piece.stats.cells_visited = cells_visited_;
        piece.stats.vertex_tolerance = vertex_tolerance_;
        piece.nan_at = nan_at_;
    }

    [[nodiscard]] int resolution() const { return resolution_; }
    [[nodiscard]] double coordinate(int index, int axis) const {
        return box_.lo[axis] + (box_.hi[axis] - box_.lo[axis]) * (static_cast<double>(index) / resolution_);
    }
    [[nodiscard]] Vec3d grid_point(int i, int j, int k) const { return {coordinate(i, 0), coordinate(j, 1), coordinate(k, 2)}; }

    /// The point of the segment from `in` (f < 0) to `out` (f ≥ 0) where f
    /// is zero, by regula falsi (Illinois) on the current block's tape: the
    /// last bracket's secant point.
    Vec3d refine(const Vec3d& in, double f_in, const Vec3d& out, double f_out);

    /// A point where f was found undefined: the walk stopped there.
    [[nodiscard]] const std::optional<Vec3d>& nan_at() const { return nan_at_; }
    /// f at the grid point (i, j, k) by the full tape, as a block's grid
    /// points are evaluated (the same lanes, so the same value to the bit);
    /// NaN stops the walk.
    double grid_value(int i, int j, int k);

private:
    template <class OnBlock>
    void visit(int i, int j, int k, int size, const Tape& tape, int level, OnBlock& on_block) {
        if (nan_at_) return;
        ++cells_visited_;
        const Box3 cell{grid_point(i, j, k), grid_point(i + size, j + size, k + size)};
        const Interval f = pruner_.evaluate(tape, cell);
        if (f.lo > 0.0 || f.hi < 0.0) return;  // no surface here (NaN bounds do not rule it out)
        const Tape& here = pruner_.simplified(tapes_[static_cast<std::size_t>(level)]);
        if (size <= block) {
            if (evaluate_block(i, j, k, size, here)) on_block(Block{i, j, k, size, &here, &block_values_});
            return;
        }
        const int half = size / 2;
        for (int c = 0; c < 8; ++c)
            visit(i + half * corner_offset(c, 0), j + half * corner_offset(c, 1), k + half * corner_offset(c, 2), half,
                  here, level + 1, on_block);
    }

    /// f at the block's grid points; false (and nan_at set) where it is NaN.
    bool evaluate_block(int i, int j, int k, int size, const Tape& tape);

    const Tape& full_;
    Box3 box_;
    int resolution_;
    TapePruner pruner_;
    Evaluator<double> points_;
    BatchEvaluator<double> grid_;       // a block's grid points at once
    BatchEvaluator<double> full_grid_;  // grid points beyond a block, on the full tape
    std::array<double, block_points * block_points * block_points> xs_{}, ys_{}, zs_{};
    std::vector<Tape> tapes_;  // one pruned tape a level of the octree
    std::array<double, block_points * block_points * block_points> block_values_{};
    std::optional<Vec3d> nan_at_;
    std::uint64_t cells_visited_ = 0;
    double vertex_tolerance_ = 0.0;  // the widest final bracket of any refine(), in scene units
};

}  // namespace zeroset
