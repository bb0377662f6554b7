// Slices: f on a plane through space — the survey's Figure 1 cut-away, and
// the "Prospero challenge" of drawing a 2-D model at a given resolution.
//
// The image is split recursively into square tiles. Over each tile one
// interval evaluation of the tape (expr/tape_pruner.hpp) both decides the
// sign of f on the whole tile when it can — the tile is then filled without
// evaluating a pixel — and prunes the tape to the clauses live there, so
// its four sub-tiles walk a shorter tape. Tiles of 16×16 pixels are
// evaluated point by point, 256 pixels in one walk of their pruned tape, in
// float SIMD lanes (expr/batch_evaluator.hpp). A 7 866-clause model
// typically reaches its leaves with a few dozen clauses.
//
// Signs decided by intervals are certain. Pixels are evaluated in float, so
// where |f| is within float rounding of 0 a pixel's sign may differ from
// the exact one.
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/render/large_buffer.hpp"

namespace zeroset {

/// The square of the plane to sample: normal to `axis` (0 = x, 1 = y, 2 = z)
/// at `at`, both in-plane coordinates over [min, max]. The image's horizontal
/// axis is the first in-plane axis of (x, y, z) — x for axis z and y, y for
/// axis x — and its vertical axis the second, increasing upwards.
struct SlicePlane {
    int axis = 2;
    double at = 0.0;
    double min = -1.0;
    double max = 1.0;
};

struct SliceSettings {
    SlicePlane plane;
    int size = 1024;              // width = height in pixels
    bool every_pixel = false;     // evaluate every pixel even where the sign is known (for values)
    int threads = 0;              // 0: all hardware threads
};

/// What the slicing cost, to compare with the full tape.
struct SliceStats {
    std::uint64_t tiles = 0;              // tiles whose interval was evaluated
    std::uint64_t tiles_decided = 0;      // tiles whose sign the interval decided
    std::uint64_t pixels_decided = 0;     // pixels in those tiles
    std::uint64_t leaf_batches = 0;       // 16×16 tiles evaluated pixel by pixel
    std::uint64_t pixels_evaluated = 0;
    std::uint64_t leaf_clauses = 0;       // clauses walked by the leaf batches, summed
    std::uint64_t interval_clauses = 0;   // clauses walked by the interval evaluations (one walk: up to four tiles)
    std::uint32_t max_leaf_slots = 0;     // the most slots a leaf tape needed
    std::size_t full_clauses = 0;
    std::uint32_t full_slots = 0;
};

/// f sampled at the pixel centres, row 0 at the top. A pixel of a tile the
/// interval decided holds the bound of f over the tile nearest to 0 (the
/// right sign, and |f| is at least that there); NaN where f is undefined.
struct SliceField {
    int size = 0;
    LargeBuffer<float> values;  // in huge pages where the kernel allows: a page fault costs ~10 µs here
    SliceStats stats;

    [[nodiscard]] float at(int x, int y) const {
        return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)];
    }
};

/// Samples `tape` on the plane. Throws RenderError for an impossible size or
/// a plane that is not finite.
SliceField slice(const Tape& tape, const SliceSettings& settings);

}  // namespace zeroset
