// Building the octree: the survey's cell tests, each cell's tape pruned from
// its parent's, the top levels breadth first and their subtrees depth first
// on all cores.
#include "zeroset/accel/octree.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_map>
#include <unordered_set>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/expr/tape_pruner.hpp"

namespace zeroset {

std::string_view partition_name(Partition partition) {
    switch (partition) {
        case Partition::Auto: return "auto";
        case Partition::None: return "none";
        case Partition::Lipschitz: return "lipschitz";
        case Partition::VertexSign: return "vertex-sign";
        case Partition::SeedFill: return "seed-fill";
    }
    return "?";
}

std::span<const Partition> all_partitions() {
    static constexpr Partition all[] = {Partition::Auto, Partition::None, Partition::Lipschitz, Partition::VertexSign,
                                        Partition::SeedFill};
    return all;
}

std::optional<Partition> partition_from_name(std::string_view name) {
    for (const Partition p : all_partitions())
        if (partition_name(p) == name) return p;
    return std::nullopt;
}

namespace {

/// A hash of everything that makes a tape what it is.
std::uint64_t fingerprint(const Tape& tape) {
    std::uint64_t h = 1469598103934665603ull;
    const auto mix = [&h](std::uint64_t v) { h = (h ^ v) * 1099511628211ull; };
    for (const Clause& c : tape.clauses()) {
        mix(static_cast<std::uint64_t>(c.op));
        mix((std::uint64_t{c.out} << 32) ^ c.a);
        mix(c.b);
    }
    for (const auto& [slot, value] : tape.constants()) mix(slot ^ std::bit_cast<std::uint64_t>(value));
    mix(tape.result_slot());
    return h;
}

bool same_tape(const Tape& p, const Tape& q) {
    const auto same_clause = [](const Clause& c, const Clause& d) {
        return c.op == d.op && c.out == d.out && c.a == d.a && c.b == d.b;
    };
    const auto same_constant = [](const std::pair<std::uint32_t, double>& c, const std::pair<std::uint32_t, double>& d) {
        return c.first == d.first && std::bit_cast<std::uint64_t>(c.second) == std::bit_cast<std::uint64_t>(d.second);
    };
    return p.result_slot() == q.result_slot() && p.slot_count() == q.slot_count() &&
           std::ranges::equal(p.clauses(), q.clauses(), same_clause) &&
           std::ranges::equal(p.constants(), q.constants(), same_constant);
}

/// 10⁻⁵ of the diagonal, and at least 64 ulps of the largest coordinate.
double cell_pad(const Box3& box) {
    const double largest = std::max(max_abs(box.lo), max_abs(box.hi));
    const double ulp = std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest;
    return std::max(1e-5 * box.diagonal(), 64.0 * ulp);
}

/// A subtree still to build: its node, box and depth, and the tape pruned
/// to its parent (owned, as the breadth-first stage moves on).
struct Task {
    std::uint32_t node;
    Box3 box;
    int depth;
    std::shared_ptr<const Tape> parent;
};

}  // namespace

/// One thread's evaluators and its part of the octree, with indices local
/// to it until Octree's constructor appends them.
class OctreeBuilder {
public:
    enum class Verdict { Empty, Keep, Undefined };
    struct Classified {
        Verdict verdict;
        const Tape* tape;  // pruned to the cell (or the parent's, when nothing pruned)
    };

    OctreeBuilder(const Tape& source, const OctreeSettings& settings, double pad, std::atomic<std::size_t>& cell_count,
                  std::atomic<std::size_t>& stored)
        : source_(source), settings_(settings), pad_(pad), pruner_(source), point_(source), centre_(source),
          slope_(source), level_(static_cast<std::size_t>(settings.max_depth) + 1), cell_count_(cell_count),
          stored_clauses_(stored) {}

    /// The survey's tests for the cell `box` at `depth`, on the parent's tape.
    Classified classify(const Box3& box, int depth, const Tape& parent) {
        const Box3 cell = pad(box);
        const Interval f = pruner_.evaluate(parent, cell);
        const Tape& tape = pruner_.simplified(level_[static_cast<std::size_t>(depth)]);
        if (f.is_empty()) return {Verdict::Undefined, &tape};  // NaN all over: kept, so a ray reports it
        if (settings_.rule == Partition::VertexSign) {
            if (depth < 2) return {Verdict::Keep, &tape};
            return {corners_differ(tape, cell) ? Verdict::Keep : Verdict::Empty, &tape};
        }
        if (f.lo > 0.0 || f.hi < 0.0) return {Verdict::Empty, &tape};
        if (corners_differ(tape, cell)) return {Verdict::Keep, &tape};
        // Kalra–Barr: no zero within r of the centre when |f(centre)| > L·r.
        const double radius = rounding::up(0.5 * cell.diagonal());
        const double bound = rounding::up(lipschitz(tape, cell) * radius);
        const Vec3d c = cell.center();
        centre_.rebind(tape);
        const Interval at_centre = centre_(Interval(c.x), Interval(c.y), Interval(c.z));
        if (at_centre.lo > bound || at_centre.hi < -bound) return {Verdict::Empty, &tape};
        return {Verdict::Keep, &tape};
    }

    /// Builds the subtree of `task` depth first; returns its root node.
    Octree::Node build(const Task& task) {
        const Classified c = classify(task.box, task.depth, *task.parent);
        // The breadth-first stage stores no tapes: the task's parent tape is
        // stored here, for the cells below that prune no further.
        std::uint32_t ref = OctreeCell::full_tape;
        std::size_t ref_clauses = source_.clauses().size();
        if (c.verdict != Verdict::Empty) {
            if (const auto stored = store(*task.parent, ref_clauses)) {
                ref = *stored;
                ref_clauses = task.parent->clauses().size();
            }
        }
        return descend(task.box, task.depth, c, ref, ref_clauses);
    }

    /// The index of `tape` among the stored tapes — stored now, unless an
    /// equal tape already is (neighbouring cells often make the same
    /// choices) — when it is clearly (10 %) shorter than the tape a cell
    /// would otherwise walk and the memory cap allows; else nothing.
    std::optional<std::uint32_t> store(const Tape& tape, std::size_t inherited_clauses) {
        if (tape.clauses().size() * 10 > inherited_clauses * 9) return std::nullopt;
        const std::uint64_t key = fingerprint(tape);
        for (auto [it, end] = stored_by_key_.equal_range(key); it != end; ++it)
            if (same_tape(tapes[it->second], tape)) return it->second;
        if (stored_clauses_.fetch_add(tape.clauses().size()) >= settings_.max_stored_clauses) return std::nullopt;
        tapes.push_back(tape);
        const auto index = static_cast<std::uint32_t>(tapes.size() - 1);
        stored_by_key_.emplace(key, index);
        return index;
    }

    /// The node for a classified cell: empty, a leaf, or 8 children built
    /// here. `inherited` is the stored tape the cell would otherwise walk.
    Octree::Node descend(const Box3& box, int depth, const Classified& c, std::uint32_t inherited,
                         std::size_t inherited_clauses) {
        if (c.verdict == Verdict::Empty) return {};
        std::uint32_t ref = inherited;
        std::size_t ref_clauses = inherited_clauses;
        if (const auto stored = store(*c.tape, inherited_clauses)) {
            ref = *stored;
            ref_clauses = c.tape->clauses().size();
        }
        const bool at_limit = depth >= settings_.max_depth || cell_count_.load() >= settings_.max_cells;
        if (c.verdict == Verdict::Undefined || at_limit) return leaf(box, *c.tape, ref);
        const auto first = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 8);
        for (int i = 0; i < 8; ++i) {
            const Box3 child = Octree::child_box(box, i);
            const Classified cc = classify(child, depth + 1, *c.tape);
            const Octree::Node n = descend(child, depth + 1, cc, ref, ref_clauses);
            nodes[first + static_cast<std::uint32_t>(i)] = n;
        }
        return {Octree::Kind::Inner, first};
    }

    /// A leaf cell walking `tape` (stored as `ref`, or the full tape).
    Octree::Node leaf(const Box3& box, const Tape& tape, std::uint32_t ref) {
        OctreeCell cell;
        cell.tape = ref;
        const Tape& walked = ref == OctreeCell::full_tape ? source_ : tapes[ref];
        cell.can_prune = walked.has_choices();
        // L for the statistics, on a sample of the cells: it is the build's
        // costliest evaluation, and rays compute their own per segment.
        if (cell_count_.fetch_add(1) % lipschitz_sample == 0) {
            cell.lipschitz = static_cast<float>(lipschitz(tape, pad(box)));
            if (std::isfinite(cell.lipschitz) && cell.lipschitz > 0.0f)
                cell.lipschitz = std::nextafter(cell.lipschitz, std::numeric_limits<float>::infinity());
        }
        cells.push_back(cell);
        boxes.push_back(box);
        return {Octree::Kind::Leaf, static_cast<std::uint32_t>(cells.size() - 1)};
    }

    std::vector<Octree::Node> nodes;
    std::vector<OctreeCell> cells;
    std::vector<Box3> boxes;
    std::vector<Tape> tapes;

private:
    [[nodiscard]] Box3 pad(const Box3& box) const { return Octree::padded(box, pad_); }
    bool corners_differ(const Tape& tape, const Box3& box) {
        point_.rebind(tape);
        bool negative = false, positive = false;
        for (int i = 0; i < 8; ++i) {
            const double v = point_(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
            negative |= v < 0.0;
            positive |= v > 0.0;
        }
        return negative && positive;
    }
    double lipschitz(const Tape& tape, const Box3& box) {
        slope_.rebind(tape);
        return lipschitz_bound(slope_, box).constant;
    }

    const Tape& source_;
    const OctreeSettings& settings_;
    double pad_;
    TapePruner pruner_;
    Evaluator<double> point_;
    Evaluator<Interval> centre_;
    Evaluator<Dual<Interval>> slope_;
    std::vector<Tape> level_;  // level_[d]: the tape pruned at depth d on the current path
    std::unordered_multimap<std::uint64_t, std::uint32_t> stored_by_key_;  // fingerprint → index in tapes
    std::atomic<std::size_t>& cell_count_;
    std::atomic<std::size_t>& stored_clauses_;
};

Octree::Octree(const Tape& tape, const Box3& box, const OctreeSettings& settings)
    : source_(&tape), root_(box), pad_(cell_pad(box)) {
    const auto start = std::chrono::steady_clock::now();
    OctreeSettings s = settings;
    s.max_depth = std::clamp(s.max_depth, 0, max_supported_depth);
    if (s.rule == Partition::SeedFill) build_by_seed_fill(s);
    else build_by_subdivision(s);
    finish_stats(s, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void Octree::build_by_subdivision(const OctreeSettings& s) {
    const Tape& tape = *source_;
    const Box3& box = root_;
    const int threads = s.threads > 0 ? s.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<std::size_t> cell_count{0}, stored{0};
    std::vector<std::unique_ptr<OctreeBuilder>> builders;
    for (int t = 0; t < threads; ++t)
        builders.push_back(std::make_unique<OctreeBuilder>(tape, s, pad_, cell_count, stored));

    // Breadth first until there is work for every thread: the nodes so made
    // are the top of nodes_; cells made there (at a small max_depth, or
    // undefined regions) come from builder 0, appended with the rest below.
    nodes_.resize(1);
    const auto shared_source = std::shared_ptr<const Tape>(source_, [](const Tape*) {});
    std::vector<Task> tasks{{0, box, 0, shared_source}};
    const std::size_t enough = 16 * static_cast<std::size_t>(threads);
    OctreeBuilder& top = *builders.front();
    std::vector<Task> ready;
    while (!tasks.empty() && tasks.size() < enough) {
        std::vector<Task> next;
        for (const Task& task : tasks) {
            const OctreeBuilder::Classified c = top.classify(task.box, task.depth, *task.parent);
            if (c.verdict == OctreeBuilder::Verdict::Empty) continue;
            if (c.verdict == OctreeBuilder::Verdict::Undefined || task.depth >= s.max_depth) {
                ready.push_back(task);  // a leaf: built (re-classified) by a builder below
                continue;
            }
            const auto first = static_cast<std::uint32_t>(nodes_.size());
            nodes_.resize(nodes_.size() + 8);
            nodes_[task.node] = {Kind::Inner, first};
            const auto pruned = std::make_shared<const Tape>(*c.tape);
            for (int i = 0; i < 8; ++i)
                next.push_back({first + static_cast<std::uint32_t>(i), child_box(task.box, i), task.depth + 1, pruned});
        }
        tasks = std::move(next);
    }
    tasks.insert(tasks.end(), ready.begin(), ready.end());

    // The subtrees, spread over the threads.
    std::vector<Node> roots(tasks.size());
    std::vector<std::size_t> owner(tasks.size());
    std::atomic<std::size_t> next_task{0};
    std::mutex progress_mutex;
    int tasks_done = 0;
    const auto run = [&](std::size_t t) {
        for (std::size_t i = next_task++; i < tasks.size(); i = next_task++) {
            roots[i] = builders[t]->build(tasks[i]);
            owner[i] = t;
            if (s.on_progress) {
                std::lock_guard lock(progress_mutex);
                s.on_progress(++tasks_done, static_cast<int>(tasks.size()));
            }
        }
    };
    {
        std::vector<std::jthread> pool;
        for (std::size_t t = 1; t < builders.size() && t < tasks.size(); ++t) pool.emplace_back(run, t);
        run(0);
    }

    // Append every builder's part, its local indices moved past what is there.
    std::vector<std::uint32_t> node_base(builders.size()), cell_base(builders.size());
    std::vector<Box3> boxes;
    for (std::size_t t = 0; t < builders.size(); ++t) {
        OctreeBuilder& b = *builders[t];
        node_base[t] = static_cast<std::uint32_t>(nodes_.size());
        cell_base[t] = static_cast<std::uint32_t>(cells_.size());
        const auto tape_base = static_cast<std::uint32_t>(tapes_.size());
        for (Node n : b.nodes) {
            if (n.kind == Kind::Inner) n.index += node_base[t];
            if (n.kind == Kind::Leaf) n.index += cell_base[t];
            nodes_.push_back(n);
        }
        for (OctreeCell c : b.cells) {
            if (c.tape != OctreeCell::full_tape) c.tape += tape_base;
            cells_.push_back(c);
        }
        boxes.insert(boxes.end(), b.boxes.begin(), b.boxes.end());
        for (Tape& stored_tape : b.tapes) tapes_.push_back(std::move(stored_tape));
    }
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        Node n = roots[i];
        if (n.kind == Kind::Inner) n.index += node_base[owner[i]];
        if (n.kind == Kind::Leaf) n.index += cell_base[owner[i]];
        nodes_[tasks[i].node] = n;
    }
    boxes_ = std::move(boxes);
}

void Octree::build_by_seed_fill(const OctreeSettings& s) {
    const int depth = s.max_depth;
    const std::int64_t n = std::int64_t{1} << depth;
    // A cell (i, j, k) of the finest grid, by halving as the walk does, so
    // that neighbours share their faces exactly.
    const auto cell_box = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        Box3 b = root_;
        for (int level = depth - 1; level >= 0; --level)
            b = child_box(b, static_cast<int>(((i >> level) & 1) | (((j >> level) & 1) << 1) | (((k >> level) & 1) << 2)));
        return b;
    };
    const auto key = [n](std::int64_t i, std::int64_t j, std::int64_t k) {
        return static_cast<std::uint64_t>((i * (n + 1) + j) * (n + 1) + k);
    };
    // The sign of f at each grid corner, evaluated once.
    constexpr int undefined = 2;
    Evaluator<double> f(*source_);
    std::unordered_map<std::uint64_t, int> corner_sign;
    const auto sign_at = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const auto [it, fresh] = corner_sign.try_emplace(key(i, j, k), 0);
        if (fresh) {
            const Box3 b = cell_box(std::min(i, n - 1), std::min(j, n - 1), std::min(k, n - 1));
            // On the surface counts as inside (the solid is f ≤ 0), so a
            // surface lying on a grid plane still has straddling cells.
            const double v = f(i == n ? b.hi.x : b.lo.x, j == n ? b.hi.y : b.lo.y, k == n ? b.hi.z : b.lo.z);
            it->second = v != v ? undefined : (v <= 0.0 ? -1 : 1);
        }
        return it->second;
    };
    // A cell with a NaN corner is kept too, so that rays still report it.
    const auto straddles = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        bool negative = false, positive = false;
        for (int c = 0; c < 8; ++c) {
            const int v = sign_at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
            if (v == undefined) return true;
            negative |= v < 0;
            positive |= v > 0;
        }
        return negative && positive;
    };

    // The seed: the first straddling cell on the three axis lines through
    // the centre, else the first of the whole grid in scan order.
    struct Cell {
        std::int64_t i, j, k;
    };
    std::optional<Cell> seed;
    const std::int64_t m = n / 2;
    for (std::int64_t t = 0; t < n && !seed; ++t)
        for (const Cell c : {Cell{t, m, m}, Cell{m, t, m}, Cell{m, m, t}})
            if (!seed && straddles(c.i, c.j, c.k)) seed = c;
    for (std::int64_t i = 0; i < n && !seed; ++i)
        for (std::int64_t j = 0; j < n && !seed; ++j)
            for (std::int64_t k = 0; k < n && !seed; ++k)
                if (straddles(i, j, k)) seed = Cell{i, j, k};

    // The seed fill over face neighbours, up to the cell cap.
    std::vector<Cell> kept, pending;
    std::unordered_set<std::uint64_t> visited;
    if (seed) {
        pending.push_back(*seed);
        visited.insert(key(seed->i, seed->j, seed->k));
    }
    while (!pending.empty() && kept.size() < s.max_cells) {
        const Cell c = pending.back();
        pending.pop_back();
        if (!straddles(c.i, c.j, c.k)) continue;
        kept.push_back(c);
        for (int axis = 0; axis < 3; ++axis) {
            for (const int step : {-1, 1}) {
                Cell next = c;
                (axis == 0 ? next.i : axis == 1 ? next.j : next.k) += step;
                if (next.i < 0 || next.j < 0 || next.k < 0 || next.i >= n || next.j >= n || next.k >= n) continue;
                if (visited.insert(key(next.i, next.j, next.k)).second) pending.push_back(next);
            }
        }
    }

    // The kept cells as leaves of the octree, each with its tape pruned to it.
    std::atomic<std::size_t> cell_count{0}, stored{0};
    OctreeSettings leaf_settings = s;
    leaf_settings.rule = Partition::Lipschitz;
    OctreeBuilder builder(*source_, leaf_settings, pad_, cell_count, stored);
    nodes_.assign(1, Node{});
    for (const Cell& c : kept) {
        std::uint32_t node = 0;
        for (int level = depth - 1; level >= 0; --level) {
            if (nodes_[node].kind == Kind::Empty) {
                nodes_[node] = {Kind::Inner, static_cast<std::uint32_t>(nodes_.size())};
                nodes_.resize(nodes_.size() + 8);
            }
            const int child =
                static_cast<int>(((c.i >> level) & 1) | (((c.j >> level) & 1) << 1) | (((c.k >> level) & 1) << 2));
            node = nodes_[node].index + static_cast<std::uint32_t>(child);
        }
        const Box3 box = cell_box(c.i, c.j, c.k);
        const OctreeBuilder::Classified pruned = builder.classify(box, depth, *source_);
        const auto ref = builder.store(*pruned.tape, source_->clauses().size());
        nodes_[node] = builder.leaf(box, *pruned.tape, ref.value_or(OctreeCell::full_tape));
    }
    cells_ = std::move(builder.cells);
    boxes_ = std::move(builder.boxes);
    tapes_ = std::move(builder.tapes);
}

void Octree::finish_stats(const OctreeSettings& s, double build_seconds) {
    const Tape& tape = *source_;
    stats_.cells = cells_.size();
    stats_.nodes = nodes_.size();
    stats_.full_clauses = tape.clauses().size();
    std::vector<double> finite;
    double clause_sum = 0.0;
    for (const OctreeCell& c : cells_) {
        clause_sum += static_cast<double>(tape_of(c).clauses().size());
        if (std::isfinite(c.lipschitz)) finite.push_back(c.lipschitz);
        if (std::isinf(c.lipschitz)) ++stats_.unbounded_cells;
    }
    for (const Tape& t : tapes_) stats_.stored_clauses += t.clauses().size();
    stats_.mean_cell_clauses = cells_.empty() ? 0.0 : clause_sum / static_cast<double>(cells_.size());
    std::sort(finite.begin(), finite.end());
    if (!finite.empty()) {
        stats_.median_lipschitz = finite[finite.size() / 2];
        stats_.p90_lipschitz = finite[finite.size() * 9 / 10];
    }
    stats_.bytes = nodes_.size() * sizeof(Node) + cells_.size() * (sizeof(OctreeCell) + sizeof(Box3)) +
                   stats_.stored_clauses * sizeof(Clause);
    for (const Tape& t : tapes_) stats_.bytes += t.constants().size() * sizeof(std::pair<std::uint32_t, double>);
    stats_.depth = s.max_depth;
    stats_.build_seconds = build_seconds;
}

}  // namespace zeroset
