// Slicing by recursive tiles: the top levels of the quadtree breadth first,
// then the subtrees below depth first, each step spread over the threads,
// each thread with its own pruner, pruned tapes (one per depth) and batch
// evaluator.
#include "zeroset/render/slice.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <span>
#include <thread>
#include <utility>

#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/render/render_settings.hpp"

namespace zeroset {

namespace {

// A leaf, after its own interval evaluation, is evaluated pixel by pixel in
// one batch of 256 lanes: on prospero.vm, 8×8 leaves cost as much in all,
// as their intervals cost about what they save.
constexpr int leaf_size = 16;
constexpr std::size_t leaf_pixels = static_cast<std::size_t>(leaf_size) * leaf_size;
constexpr int max_depth = 16;
/// The corners of a tile's four sub-tiles, in units of their side.
constexpr std::array<std::pair<int, int>, 4> quadrants{{{0, 0}, {1, 0}, {0, 1}, {1, 1}}};  // more than the halvings from any task's tile (≤ 2^16 pixels) to a leaf

/// The corner of sub-tile k of the tile at (x0, y0) whose sub-tiles have side `half`.
std::pair<int, int> quadrant_corner(int x0, int y0, int half, std::size_t k) {
    return {x0 + quadrants[k].first * half, y0 + quadrants[k].second * half};
}

void check_settings(const SliceSettings& s) {
    require_in_range(s.size, 1, max_image_side, "size");
    require_image_fits(s.size, s.size);
    require_in_range(s.threads, 0, 4096, "threads");
    require_in_range(s.plane.axis, 0, 2, "axis");
    const SlicePlane& p = s.plane;
    if (!(std::isfinite(p.at) && std::isfinite(p.min) && std::isfinite(p.max)))
        throw RenderError("the slice's plane and square must be finite");
    if (!(p.min < p.max)) throw RenderError("the slice's square is empty (need min < max)");
    // Pixels are sampled in float: the square must lie well inside its range.
    constexpr double float_reach = 1e30;
    if (std::abs(p.at) > float_reach || std::abs(p.min) > float_reach || std::abs(p.max) > float_reach)
        throw RenderError("the slice's plane and square must lie within ±1e30 (pixels are sampled in float)");
}

/// Where the pixel centres lie in space. Coordinates are computed once, in
/// float — the precision pixels are evaluated in — and tile boxes are made
/// of those same floats, so every evaluated point lies in its tile's box.
class PixelGrid {
public:
    explicit PixelGrid(const SliceSettings& s) : axis_(s.plane.axis), at_(static_cast<float>(s.plane.at)) {
        const double step = (s.plane.max - s.plane.min) / s.size;
        for (int i = 0; i < s.size; ++i) {
            across_.push_back(static_cast<float>(s.plane.min + (i + 0.5) * step));
            up_.push_back(static_cast<float>(s.plane.max - (i + 0.5) * step));  // row 0 at the top
        }
        // Rounding to float is monotone, but two neighbouring centres may round
        // alike; the boxes stay correct, as they only need lo ≤ hi.
    }

    /// The points of pixels [x0, x1) × [y0, y1), row by row, into x, y and z.
    void points(int x0, int y0, int x1, int y1, float* x, float* y, float* z) const {
        // Which of x, y, z runs across the image, which up, and which is the plane's.
        float* across = axis_ == 0 ? y : x;
        float* up = axis_ == 2 ? y : z;
        float* at = axis_ == 0 ? x : axis_ == 1 ? y : z;
        std::size_t n = 0;
        for (int j = y0; j < y1; ++j)
            for (int i = x0; i < x1; ++i, ++n) {
                across[n] = across_[static_cast<std::size_t>(i)];
                up[n] = up_[static_cast<std::size_t>(j)];
            }
        std::fill_n(at, n, at_);
    }

    /// The box around the centres of pixels [x0, x1) × [y0, y1).
    [[nodiscard]] Box3 box(int x0, int y0, int x1, int y1) const {
        const std::array<float, 3> lo = place(across_[x0], up_[y1 - 1]), hi = place(across_[x1 - 1], up_[y0]);
        return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    }

private:
    [[nodiscard]] std::array<float, 3> place(float across, float up) const {
        switch (axis_) {
            case 0: return {at_, across, up};
            case 1: return {across, at_, up};
            default: return {across, up, at_};
        }
    }

    int axis_;
    float at_;
    std::vector<float> across_, up_;
};

/// A decided tile's value: the bound of f nearest 0, rounded towards 0 but
/// never to 0, so |f| is at least its magnitude all over the tile.
float decided_value(const Interval& f) {
    constexpr float smallest = std::numeric_limits<float>::denorm_min();
    const double bound = f.lo > 0.0 ? f.lo : f.hi;
    float value = static_cast<float>(bound);
    if (std::abs(static_cast<double>(value)) > std::abs(bound)) value = std::nextafter(value, 0.0f);
    return f.lo > 0.0 ? std::max(value, smallest) : std::min(value, -smallest);
}

/// One thread's tools: the pruner, a tape per depth, the batch evaluator.
class TileVisitor {
public:
    TileVisitor(const Tape& full, const PixelGrid& grid, const SliceSettings& settings, LargeBuffer<float>& values)
        : grid_(grid), size_(settings.size), every_pixel_(settings.every_pixel), values_(values), pruner_(full),
          pruned_(max_depth) {}

    /// Evaluates f over the tile of side `side` at (x0, y0) with `parent`'s
    /// tape. Fills the tile when its sign is decided and returns nullptr;
    /// else returns the tape for the tile: `pruned`, pruned to the tile, or
    /// `parent` itself when no min or max could be pruned there.
    const Tape* visit(int x0, int y0, int side, const Tape& parent, Tape& pruned) {
        const int x1 = std::min(x0 + side, size_), y1 = std::min(y0 + side, size_);
        const Interval f = pruner_.evaluate(parent, grid_.box(x0, y0, x1, y1));
        stats.interval_clauses += parent.clauses().size();
        if (fill_if_decided(x0, y0, x1, y1, f)) return nullptr;
        return &pruner_.simplified(pruned);
    }

    /// The four sub-tiles of a tile whose sign is not decided, given the
    /// tape pruned to it, evaluated in one walk of that tape, each in a lane
    /// of its own. Fills those whose sign is decided; returns the tapes of
    /// the others (in `pruned`, or `tape` itself) and nullptr for the rest.
    std::array<const Tape*, 4> split(int x0, int y0, int side, const Tape& tape, std::array<Tape, 4>& pruned) {
        const int half = side / 2;
        std::array<Box3, TapePruner::lanes> boxes;
        std::array<bool, TapePruner::lanes> in_image{};
        for (std::size_t k = 0; k < quadrants.size(); ++k) {
            const auto [qx, qy] = quadrant_corner(x0, y0, half, k);
            in_image[k] = qx < size_ && qy < size_;
            // A sub-tile outside the image takes the first one's box: it is skipped below.
            boxes[k] = in_image[k] ? grid_.box(qx, qy, std::min(qx + half, size_), std::min(qy + half, size_)) : boxes[0];
        }
        const IntervalLanes f = pruner_.evaluate(tape, boxes);
        stats.interval_clauses += tape.clauses().size();
        std::array<const Tape*, 4> below{};
        for (std::size_t k = 0; k < quadrants.size(); ++k) {
            if (!in_image[k]) continue;
            const auto [qx, qy] = quadrant_corner(x0, y0, half, k);
            const int lane = static_cast<int>(k);
            if (!fill_if_decided(qx, qy, std::min(qx + half, size_), std::min(qy + half, size_), f.lane(lane)))
                below[k] = &pruner_.simplified(pruned[k], lane);
        }
        return below;
    }

    /// The whole quadtree below a tile whose sign is not decided, depth
    /// first, given the tape pruned to it.
    void descend(int x0, int y0, int side, const Tape& tape, int depth) {
        if (side <= leaf_size) {
            evaluate_leaf(x0, y0, tape);
            return;
        }
        const int half = side / 2;
        const std::array<const Tape*, 4> below = split(x0, y0, side, tape, pruned_[static_cast<std::size_t>(depth)]);
        for (std::size_t k = 0; k < quadrants.size(); ++k) {
            if (!below[k]) continue;
            const auto [qx, qy] = quadrant_corner(x0, y0, half, k);
            descend(qx, qy, half, *below[k], depth + 1);
        }
    }

    SliceStats stats;

private:
    float* row(int y) { return values_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(size_); }

    /// Counts the tile [x0, x1) × [y0, y1), over which f lies in `f`, and
    /// fills it when that decides its sign (never in every-pixel mode).
    bool fill_if_decided(int x0, int y0, int x1, int y1, const Interval& f) {
        ++stats.tiles;
        const bool undefined = f.is_empty();
        if (every_pixel_ || !(f.lo > 0.0 || f.hi < 0.0 || undefined)) return false;
        const float value = undefined ? std::numeric_limits<float>::quiet_NaN() : decided_value(f);
        for (int y = y0; y < y1; ++y) std::fill(row(y) + x0, row(y) + x1, value);
        ++stats.tiles_decided;
        stats.pixels_decided += static_cast<std::uint64_t>(x1 - x0) * static_cast<std::uint64_t>(y1 - y0);
        return true;
    }

    void evaluate_leaf(int x0, int y0, const Tape& tape) {
        static_assert(leaf_pixels <= BatchEvaluator<float>::lanes, "a leaf is one batch");
        const int x1 = std::min(x0 + leaf_size, size_), y1 = std::min(y0 + leaf_size, size_);
        batch_.rebind(tape);
        const BatchEvaluator<float>::Inputs in = batch_.inputs();
        grid_.points(x0, y0, x1, y1, in.x, in.y, in.z);
        const std::span<const float> values = batch_.evaluate_in_place();
        std::size_t n = 0;
        for (int y = y0; y < y1; ++y, n += static_cast<std::size_t>(x1 - x0))
            std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(n), x1 - x0, row(y) + x0);
        ++stats.leaf_batches;
        stats.pixels_evaluated += n;
        stats.leaf_clauses += tape.clauses().size();
        stats.max_leaf_slots = std::max(stats.max_leaf_slots, tape.slot_count());
    }

    const PixelGrid& grid_;
    int size_;
    bool every_pixel_;
    LargeBuffer<float>& values_;
    TapePruner pruner_;
    BatchEvaluator<float> batch_;  // bound to each leaf's tape in turn
    std::vector<std::array<Tape, TapePruner::lanes>> pruned_;  // pruned_[d]: the tapes of the sub-tiles of the tile at depth d
};

void add(SliceStats& total, const SliceStats& part) {
    total.tiles += part.tiles;
    total.tiles_decided += part.tiles_decided;
    total.pixels_decided += part.pixels_decided;
    total.leaf_batches += part.leaf_batches;
    total.pixels_evaluated += part.pixels_evaluated;
    total.leaf_clauses += part.leaf_clauses;
    total.interval_clauses += part.interval_clauses;
    total.max_leaf_slots = std::max(total.max_leaf_slots, part.max_leaf_slots);
}

/// A tile for a worker whose sign is not decided, and the tape pruned to it.
struct Task {
    int x0, y0;
    const Tape* tape;
};

}  // namespace

/// Calls work(visitor, i) for every i < count, spread over the visitors'
/// threads (visitor 0 on this one).
template <class Work>
void in_parallel(std::vector<TileVisitor>& visitors, std::size_t count, const Work& work) {
    std::atomic<std::size_t> next{0};
    const auto run = [&](TileVisitor& visitor) {
        for (std::size_t i = next++; i < count; i = next++) work(visitor, i);
    };
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < std::min(visitors.size(), count); ++t) pool.emplace_back(run, std::ref(visitors[t]));
    run(visitors[0]);
}

SliceField slice(const Tape& tape, const SliceSettings& settings) {
    check_settings(settings);
    SliceField field;
    field.size = settings.size;
    field.values.resize(static_cast<std::size_t>(settings.size) * static_cast<std::size_t>(settings.size));
    const PixelGrid grid(settings);

    int root_side = leaf_size;
    while (root_side < settings.size) root_side *= 2;
    const int thread_count =
        settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<TileVisitor> visitors;
    visitors.reserve(static_cast<std::size_t>(thread_count));
    for (int t = 0; t < thread_count; ++t) visitors.emplace_back(tape, grid, settings, field.values);

    // The root, then the levels above the tasks breadth first, each level's
    // tiles split in parallel; then the tasks' subtrees depth first, in
    // parallel. Every tile in `tasks` is one whose sign is not decided.
    const int task_side = std::max(2 * leaf_size, root_side / 16);  // up to 16 × 16 tasks
    Tape root_tape;
    const Tape* root = visitors[0].visit(0, 0, root_side, tape, root_tape);
    std::vector<Task> tasks;
    if (root) tasks.push_back({0, 0, root});
    std::deque<std::vector<std::array<Tape, 4>>> level_tapes;  // stable addresses for the tiles below
    for (int side = root_side; side > task_side; side /= 2) {
        std::vector<std::array<Tape, 4>>& tapes = level_tapes.emplace_back(tasks.size());
        std::vector<std::array<const Tape*, 4>> split(tasks.size());
        in_parallel(visitors, tasks.size(), [&](TileVisitor& visitor, std::size_t i) {
            split[i] = visitor.split(tasks[i].x0, tasks[i].y0, side, *tasks[i].tape, tapes[i]);
        });
        std::vector<Task> below;
        const int half = side / 2;
        for (std::size_t i = 0; i < tasks.size(); ++i)
            for (std::size_t k = 0; k < quadrants.size(); ++k) {
                if (!split[i][k]) continue;
                const auto [qx, qy] = quadrant_corner(tasks[i].x0, tasks[i].y0, half, k);
                below.push_back({qx, qy, split[i][k]});
            }
        tasks = std::move(below);
    }
    in_parallel(visitors, tasks.size(), [&](TileVisitor& visitor, std::size_t i) {
        visitor.descend(tasks[i].x0, tasks[i].y0, task_side, *tasks[i].tape, 0);
    });

    for (const TileVisitor& v : visitors) add(field.stats, v.stats);
    field.stats.full_clauses = tape.clauses().size();
    field.stats.full_slots = tape.slot_count();
    return field;
}

}  // namespace zeroset
