// Front-to-back voxel splitting over a tile's frustum: depth slabs while a
// voxel is deeper than wide, quarters of its pixels otherwise, four parts
// enclosed in one walk of interval lanes.
#include "zeroset/accel/frustum_cull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zeroset {

namespace {

constexpr double unreached = std::numeric_limits<double>::infinity();

// Boxes are widened by this much of the magnitudes their corners are
// computed from: far more than the rounding of a corner, or of a ray's
// point — o + t·d, with d normalised and carried through the instances'
// maps — so that every point a ray of the pixel evaluates lies in its
// voxel's box.
constexpr double box_pad = 1e-10;

// A pixel's voxels are split in depth until they are this many pixels deep:
// finer ones cost more culling than the rays' steps they save (bear.vm at
// 512²: 2.2 M evaluations at 1 pixel, 1.3 M at 4 — fewer interval
// evaluations, a few more point ones).
constexpr double leaf_depth_in_pixels = 4.0;

double largest_magnitude(const Vec3d& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

FrustumCuller::FrustumCuller(const Tape& tape) : tape_(&tape), pruner_(tape), pruned_(max_levels) {}

void FrustumCuller::cull(const CameraFrustum& frustum, const Box3& box, std::vector<double>& first_depth,
                         TraceCounters& counters) {
    frustum_ = frustum;
    box_ = box;
    counters_ = &counters;
    first_depth_ = &first_depth;
    first_depth.assign(static_cast<std::size_t>(frustum.pixels()), unreached);
    // The depths of the box, a little wider than its corners' rounded ones.
    const std::optional<Span> depths = frustum.depths_of(box);
    if (!depths) {  // a degenerate frustum: cull nothing
        std::fill(first_depth.begin(), first_depth.end(), 0.0);
        return;
    }
    double s_lo = depths->t0, s_hi = depths->t1;
    const double margin = box_pad * std::max(std::abs(s_lo), std::abs(s_hi));
    s_lo = std::max(0.0, s_lo - margin);  // the rays start at the eye
    s_hi += margin;
    if (s_hi < s_lo) return;  // the box is behind the eye
    const Voxel root{0, 0, frustum.columns, frustum.rows, s_lo, s_hi};
    const Box3 root_box = box_of(root);
    if (!root_box.valid()) return;
    ++counters.interval_evaluations;
    if (pruner_.evaluate(*tape_, root_box).lo > 0.0) return;
    descend(root, pruner_.simplified(root_tape_), 0);
}

Box3 FrustumCuller::box_of(const Voxel& v) const {
    const CameraFrustum& f = frustum_;
    const double u[2] = {f.u0 + v.i0 * f.du, f.u0 + v.i1 * f.du};
    const double w[2] = {f.v0 + v.j0 * f.dv, f.v0 + v.j1 * f.dv};
    const double s[2] = {v.s0, v.s1};
    Box3 b{{unreached, unreached, unreached}, {-unreached, -unreached, -unreached}};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p = f.at(s[corner >> 2], u[corner & 1], w[(corner >> 1) & 1]);
        b.lo = min(b.lo, p);
        b.hi = max(b.hi, p);
    }
    const double reach = std::max(std::abs(u[0]), std::abs(u[1])) * largest_magnitude(f.right) +
                         std::max(std::abs(w[0]), std::abs(w[1])) * largest_magnitude(f.up) +
                         largest_magnitude(f.forward);
    const double pad = box_pad * (largest_magnitude(f.origin) + v.s1 * reach +
                                  std::max(largest_magnitude(b.lo), largest_magnitude(b.hi))) +
                       std::numeric_limits<double>::min();
    const Vec3d widen{pad, pad, pad};
    return overlap({b.lo - widen, b.hi + widen}, box_);
}

int FrustumCuller::split(const Voxel& v, std::array<Voxel, TapePruner::lanes>& parts) const {
    const CameraFrustum& f = frustum_;
    const int columns = v.i1 - v.i0, rows = v.j1 - v.j0;
    const double deep = (v.s1 - v.s0) * length(f.forward);
    const double wide = v.s1 * std::max(columns * std::abs(f.du) * length(f.right), rows * std::abs(f.dv) * length(f.up));
    if ((columns == 1 && rows == 1) || deep > 2.0 * wide) {
        // Four slabs, front to back; the last ends exactly at s1.
        const double step = (v.s1 - v.s0) / 4.0;
        for (int k = 0; k < 4; ++k) {
            const double s0 = k == 0 ? v.s0 : v.s0 + k * step;
            const double s1 = k == 3 ? v.s1 : v.s0 + (k + 1) * step;
            parts[static_cast<std::size_t>(k)] = {v.i0, v.j0, v.i1, v.j1, s0, s1};
        }
        return 4;
    }
    const int im = columns > 1 ? v.i0 + columns / 2 : v.i1, jm = rows > 1 ? v.j0 + rows / 2 : v.j1;
    int n = 0;
    for (const auto& [i0, i1] : {std::pair{v.i0, im}, std::pair{im, v.i1}})
        for (const auto& [j0, j1] : {std::pair{v.j0, jm}, std::pair{jm, v.j1}})
            if (i0 < i1 && j0 < j1) parts[static_cast<std::size_t>(n++)] = {i0, j0, i1, j1, v.s0, v.s1};
    return n;
}

bool FrustumCuller::settled(const Voxel& v) const {
    for (int j = v.j0; j < v.j1; ++j)
        for (int i = v.i0; i < v.i1; ++i)
            if ((*first_depth_)[static_cast<std::size_t>(j * frustum_.columns + i)] == unreached) return false;
    return true;
}

bool FrustumCuller::is_leaf(const Voxel& v, int level) const {
    const CameraFrustum& f = frustum_;
    const bool one_pixel = v.i1 - v.i0 == 1 && v.j1 - v.j0 == 1;
    const bool thin = (v.s1 - v.s0) * length(f.forward) <=
                      leaf_depth_in_pixels * v.s1 *
                          std::max(std::abs(f.du) * length(f.right), std::abs(f.dv) * length(f.up));
    return (one_pixel && thin) || level == max_levels;
}

void FrustumCuller::descend(const Voxel& v, const Tape& tape, int level) {
    const CameraFrustum& f = frustum_;
    if (is_leaf(v, level)) {
        for (int j = v.j0; j < v.j1; ++j)
            for (int i = v.i0; i < v.i1; ++i) {
                double& depth = (*first_depth_)[static_cast<std::size_t>(j * f.columns + i)];
                depth = std::min(depth, v.s0);
            }
        return;
    }
    std::array<Voxel, TapePruner::lanes> parts;
    const int count = split(v, parts);
    std::array<Box3, TapePruner::lanes> boxes;
    std::array<bool, TapePruner::lanes> inside{};
    int any_inside = -1;
    for (int k = 0; k < count; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        boxes[kk] = box_of(parts[kk]);
        inside[kk] = boxes[kk].valid();
        if (inside[kk] && any_inside < 0) any_inside = k;
    }
    if (any_inside < 0) return;  // all of the voxel is outside the box
    for (std::size_t k = 0; k < boxes.size(); ++k)  // lanes with no part of their own take a valid box
        if (!inside[k]) boxes[k] = boxes[static_cast<std::size_t>(any_inside)];
    const IntervalLanes enclosures = pruner_.evaluate(tape, boxes);
    std::array<const Tape*, TapePruner::lanes> below{};
    for (int k = 0; k < count; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        if (!inside[kk]) continue;
        ++counters_->interval_evaluations;
        // Not proven empty (a NaN enclosure proves nothing): pruned now, as
        // the walks below overwrite what the pruner recorded — unless it is
        // a leaf, whose tape is never walked.
        if (enclosures.lane(k).lo > 0.0) continue;
        below[kk] = is_leaf(parts[kk], level + 1) ? &tape
                                                  : &pruner_.simplified(pruned_[static_cast<std::size_t>(level)][kk], k);
    }
    for (int k = 0; k < count; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        if (below[kk] && !settled(parts[kk])) descend(parts[kk], *below[kk], level + 1);
    }
}

const std::vector<double>* CulledTiles::first_depths(const CameraFrustum& tile, const Box3& box,
                                                    TraceCounters& counters) {
    ++uses_;
    for (Culled& c : culled_)
        if (c.tile.same_as(tile)) {
            c.last_use = uses_;
            return &c.first_depth;
        }
    if (stopped_) return nullptr;
    if (cullings_ >= 32 && uses_ < 64 * cullings_) {
        stopped_ = true;
        return nullptr;
    }
    ++cullings_;
    Culled* slot = nullptr;
    if (culled_.size() < capacity) {
        slot = &culled_.emplace_back();
    } else {  // the least recently used
        slot = &*std::min_element(culled_.begin(), culled_.end(),
                                  [](const Culled& a, const Culled& b) { return a.last_use < b.last_use; });
    }
    slot->tile = tile;
    slot->last_use = uses_;
    culler_.cull(tile, box, slot->first_depth, counters);
    return &slot->first_depth;
}

}  // namespace zeroset
