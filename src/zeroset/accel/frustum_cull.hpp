// FrustumCuller: where the camera rays of one image tile may first meet an
// implicit solid, found before any of them is traced — interval analysis
// over the tile's frustum cut into voxels of pixels × depth, front to back
// (issue 10's image-space culling, after fidget and MPR; the survey's
// interval method of §4.4 over the frustum instead of along one ray).
//
// A voxel whose enclosure of f is positive, or that lies outside the
// leaf's box, holds none of the solid {f ≤ 0} ∩ box. For each pixel the
// first voxel not proven so gives the depth its rays can start at; a pixel
// whose voxels are all proven misses the solid. A voxel is split into four
// slabs in depth while it is deeper than wide, else into four across the
// image; each split is one walk of four interval lanes over the tape pruned
// to the voxel (expr/tape_pruner.hpp), so the tape shortens as the voxels
// shrink. Splitting stops at single pixels a few pixels deep.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

class FrustumCuller {
public:
    /// For the solid {f ≤ 0} of `tape`.
    explicit FrustumCuller(const Tape& tape);

    /// Culls the frustum's tile against the solid {f ≤ 0} ∩ box, all in
    /// the solid's space: first_depth[j·columns + i] gets a depth below
    /// which no ray of pixel (i, j) meets the solid, or +∞ when none meets
    /// it at all. Counts each voxel's enclosure as an interval evaluation.
    void cull(const CameraFrustum& frustum, const Box3& box, std::vector<double>& first_depth,
              TraceCounters& counters);

    /// The most levels of splitting below the tile: a bound on the work
    /// whatever the depths (a split divides a voxel's depth by four or its
    /// pixels by up to four).
    static constexpr int max_levels = 48;

private:
    /// Pixels [i0, i1) × [j0, j1) of the tile, depths [s0, s1].
    struct Voxel {
        int i0, j0, i1, j1;
        double s0, s1;
    };
    /// The box around the voxel's points, within the solid's box; not
    /// valid() when the voxel lies outside it.
    [[nodiscard]] Box3 box_of(const Voxel& v) const;
    /// The voxel's four parts, and how many of them there are.
    [[nodiscard]] int split(const Voxel& v, std::array<Voxel, TapePruner::lanes>& parts) const;
    /// Whether the voxel, `level` splits below the tile, is split no more.
    [[nodiscard]] bool is_leaf(const Voxel& v, int level) const;
    /// Whether every pixel of the voxel already has its first depth.
    [[nodiscard]] bool settled(const Voxel& v) const;
    /// The voxel's pixels, not proven empty anywhere in front of it: the
    /// voxel is not proven empty either, and `tape` is f pruned to it.
    void descend(const Voxel& v, const Tape& tape, int level);

    const Tape* tape_;
    TapePruner pruner_;
    std::vector<std::array<Tape, TapePruner::lanes>> pruned_;  // pruned_[level]: the tapes of a voxel's parts
    Tape root_tape_;
    CameraFrustum frustum_;
    Box3 box_;
    TraceCounters* counters_ = nullptr;
    std::vector<double>* first_depth_ = nullptr;  // cull()'s
};

/// One thread's recent cullings for one solid: the tiles its camera rays
/// came from, each in the space of the instance they came through (a tile
/// often sees a few instances of a shape at once), so that the rays of a
/// tile share one culling per instance.
class CulledTiles {
public:
    explicit CulledTiles(const Tape& tape) : culler_(tape) {}

    /// The first depths of the tile's pixels (FrustumCuller::cull), culled
    /// now unless the tile was among the last few; nullptr for the tiles
    /// after culling has stopped paying here — once 32 or more cullings
    /// have served fewer than 64 rays each on average (many instances in
    /// each tile, each small on screen; a culling costs about as much as
    /// tracing a few rays) — so that it never costs much more than it saves.
    const std::vector<double>* first_depths(const CameraFrustum& tile, const Box3& box, TraceCounters& counters);

    static constexpr std::size_t capacity = 8;

private:
    struct Culled {
        CameraFrustum tile;
        std::vector<double> first_depth;
        std::uint64_t last_use = 0;
    };
    FrustumCuller culler_;
    std::vector<Culled> culled_;
    std::uint64_t uses_ = 0, cullings_ = 0;
    bool stopped_ = false;
};

}  // namespace zeroset
