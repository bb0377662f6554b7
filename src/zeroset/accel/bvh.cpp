// Binned-SAH build, in parallel for large subtrees, then flattened into
// depth-first order.
#include "zeroset/accel/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <future>
#include <memory>
#include <thread>

namespace zeroset {

namespace {

constexpr int bin_count = 16;
constexpr std::size_t max_leaf_size = 4;
constexpr std::size_t median_split_depth = 96;    // past this, split at the median (bounds the depth)
constexpr std::size_t parallel_threshold = 4096;  // subtrees smaller than this are built on one thread

struct Item {
    Box3 box;
    Vec3d centroid;
    std::uint32_t index;
};

/// The float nearest below (above) a double: boxes stored in floats still contain what they bound.
float round_down(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float round_up(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

double half_area(const Box3& b) {
    if (!b.valid()) return 0.0;
    const Vec3d s = b.size();
    return s.x * s.y + s.y * s.z + s.z * s.x;
}

struct Split {
    int axis = -1;
    double position = 0.0;  // centroids below it go left
    double cost = INFINITY;
};

/// The cheapest binned SAH split of the items, if any separates them.
Split best_split(std::span<const Item> items, const Box3& centroids) {
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
        if (!(extent > 0.0)) continue;
        std::array<Box3, bin_count> bin_box;
        std::array<std::size_t, bin_count> bin_items{};
        bin_box.fill(empty_box());
        const auto bin_of = [&](const Item& item) {
            // Clamped as a double: an infinite box's centroid makes the fraction
            // ±∞ or NaN, which no int holds (NaN goes to bin 0).
            const double f = bin_count * ((item.centroid[axis] - lo) / extent);
            return f > 0.0 ? static_cast<int>(std::min(f, static_cast<double>(bin_count - 1))) : 0;
        };
        for (const Item& item : items) {
            const int b = bin_of(item);
            bin_box[b] = united(bin_box[b], item.box);
            ++bin_items[b];
        }
        // Sweep from the right for the right-hand sides' areas, then from the left.
        std::array<double, bin_count> right_cost{};
        Box3 right = empty_box();
        std::size_t right_count = 0;
        for (int b = bin_count - 1; b > 0; --b) {
            right = united(right, bin_box[b]);
            right_count += bin_items[b];
            right_cost[b] = half_area(right) * static_cast<double>(right_count);
        }
        Box3 left = empty_box();
        std::size_t left_count = 0;
        for (int b = 0; b < bin_count - 1; ++b) {
            left = united(left, bin_box[b]);
            left_count += bin_items[b];
            if (left_count == 0 || left_count == items.size()) continue;
            const double cost = half_area(left) * static_cast<double>(left_count) + right_cost[b + 1];
            if (cost < best.cost) best = {axis, lo + extent * (b + 1) / bin_count, cost};
        }
    }
    return best;
}

}  // namespace

struct Bvh::BuildNode {
    Box3 box;
    std::unique_ptr<BuildNode> left, right;
    std::size_t first = 0, count = 0;  // a leaf's items in the item array
};

namespace {

std::unique_ptr<Bvh::BuildNode> build(std::span<Item> items, std::size_t offset, std::size_t depth, int spare_threads) {
    auto node = std::make_unique<Bvh::BuildNode>();
    Box3 box = empty_box(), centroids = empty_box();
    for (const Item& item : items) {
        box = united(box, item.box);
        centroids = united(centroids, {item.centroid, item.centroid});
    }
    node->box = box;
    const auto make_leaf = [&] {
        node->first = offset;
        node->count = items.size();
        return std::move(node);
    };
    if (items.size() <= 1) return make_leaf();

    std::size_t middle = 0;
    const Split split = depth < median_split_depth ? best_split(items, centroids) : Split{};
    const double leaf_cost = half_area(box) * static_cast<double>(items.size());
    if (split.axis >= 0 && (items.size() > max_leaf_size || split.cost + half_area(box) < leaf_cost)) {
        const auto right = std::partition(items.begin(), items.end(), [&](const Item& item) {
            return item.centroid[split.axis] < split.position;
        });
        middle = static_cast<std::size_t>(right - items.begin());
    }
    if (middle == 0 || middle == items.size()) {
        if (items.size() <= max_leaf_size) return make_leaf();
        // No useful split (equal centroids, or too deep): halve along the widest axis.
        const Vec3d extent = centroids.size();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        middle = items.size() / 2;
        std::nth_element(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(middle), items.end(),
                         [axis](const Item& p, const Item& q) { return p.centroid[axis] < q.centroid[axis]; });
    }
    const std::span<Item> left = items.first(middle), right = items.subspan(middle);
    if (spare_threads > 0 && items.size() >= parallel_threshold) {
        const int each = (spare_threads - 1) / 2;
        auto left_task = std::async(std::launch::async, [&] { return build(left, offset, depth + 1, each); });
        node->right = build(right, offset + middle, depth + 1, spare_threads - 1 - each);
        node->left = left_task.get();
    } else {
        node->left = build(left, offset, depth + 1, 0);
        node->right = build(right, offset + middle, depth + 1, 0);
    }
    return node;
}

}  // namespace

Bvh::Bvh(std::span<const Box3> boxes, int threads) {
    if (boxes.empty()) return;
    std::vector<Item> items(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
        items[i] = {boxes[i], boxes[i].center(), static_cast<std::uint32_t>(i)};
    const int thread_count = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const std::unique_ptr<BuildNode> root = build(items, 0, 0, thread_count - 1);
    order_.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) order_[i] = items[i].index;
    nodes_.reserve(items.size());
    root_box_ = root->box;
    root_ = child_of(*root, 1);
}

Bvh::Child Bvh::child_of(const BuildNode& node, std::size_t depth) {
    depth_ = std::max(depth_, depth);
    if (node.count > 0) return {static_cast<std::uint32_t>(node.first), static_cast<std::uint32_t>(node.count)};
    return {flatten(node, depth), 0};
}

std::uint32_t Bvh::flatten(const BuildNode& node, std::size_t depth) {
    // Up to four children: the binary node's two, then the largest interior
    // one replaced by its own two, while there is room.
    std::vector<const BuildNode*> children{node.left.get(), node.right.get()};
    while (children.size() < static_cast<std::size_t>(width)) {
        const auto largest = std::ranges::max_element(children, [](const BuildNode* p, const BuildNode* q) {
            const bool p_open = p->count == 0, q_open = q->count == 0;
            if (p_open != q_open) return !p_open;  // interior nodes first
            return half_area(p->box) < half_area(q->box);
        });
        if ((*largest)->count > 0) break;  // only leaves left
        const BuildNode* expanded = *largest;
        *largest = expanded->left.get();
        children.push_back(expanded->right.get());
    }
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    for (int c = 0; c < width; ++c) {
        const auto slot = static_cast<std::size_t>(c);
        Child child{empty_slot, 0};
        Box3 box{{0, 0, 0}, {0, 0, 0}};
        if (slot < children.size()) {
            box = children[slot]->box;
            child = child_of(*children[slot], depth + 1);
        }
        Node& n = nodes_[index];  // (re)taken: the recursion above may grow nodes_
        for (int axis = 0; axis < 3; ++axis) {
            n.lo[axis][slot] = round_down(box.lo[axis]);
            n.hi[axis][slot] = round_up(box.hi[axis]);
        }
        n.child[c] = child;
    }
    return index;
}

namespace {

/// What a traversal needs of its ray: origin and 1/x_d, with a zero
/// component's inverse huge but finite, so 0 · (1/x_d) is never NaN.
struct RayInverse {
    Vec3d origin;
    Vec3d inverse;
};

/// The slab test of a node's four children: entry and exit t per child, in
/// GCC/Clang vector extensions — one vector of four doubles where the target
/// has AVX2, two vectors of two on plain x86-64 (SSE2) or ARM (NEON): a
/// vector wider than the target's registers is lowered badly. The node's
/// boxes are floats, widened here.
using Double2 = double __attribute__((vector_size(16)));
using Double4 = double __attribute__((vector_size(32)));

template <class V>
[[gnu::always_inline]] inline void narrow_slabs(V& near, V& far, const V& lo, const V& hi, double o, double inverse) {
    const V a = (lo - o) * inverse, b = (hi - o) * inverse;
    const V entry = a < b ? a : b, exit = (a < b ? b : a) * (1.0 + 4e-16);  // rounding of the slab distances
    near = near < entry ? entry : near;
    far = exit < far ? exit : far;
}

struct FourLanes {
    template <class Node>
    [[gnu::always_inline]] static inline void run(const Node& node, const RayInverse& r, double t_min, double t_max,
                                                  double (&t_in)[4], double (&t_out)[4]) {
        Double4 near = {t_min, t_min, t_min, t_min}, far = {t_max, t_max, t_max, t_max};
        for (int axis = 0; axis < 3; ++axis) {
            const auto& lo = node.lo[axis];
            const auto& hi = node.hi[axis];
            narrow_slabs(near, far, Double4{lo[0], lo[1], lo[2], lo[3]}, Double4{hi[0], hi[1], hi[2], hi[3]},
                         r.origin[axis], r.inverse[axis]);
        }
        for (int c = 0; c < 4; ++c) {
            t_in[c] = near[c];
            t_out[c] = far[c];
        }
    }
};

struct TwoPairs {
    template <class Node>
    [[gnu::always_inline]] static inline void run(const Node& node, const RayInverse& r, double t_min, double t_max,
                                                  double (&t_in)[4], double (&t_out)[4]) {
        Double2 near[2] = {{t_min, t_min}, {t_min, t_min}}, far[2] = {{t_max, t_max}, {t_max, t_max}};
        for (int axis = 0; axis < 3; ++axis) {
            const auto& lo = node.lo[axis];
            const auto& hi = node.hi[axis];
            narrow_slabs(near[0], far[0], Double2{lo[0], lo[1]}, Double2{hi[0], hi[1]}, r.origin[axis], r.inverse[axis]);
            narrow_slabs(near[1], far[1], Double2{lo[2], lo[3]}, Double2{hi[2], hi[3]}, r.origin[axis], r.inverse[axis]);
        }
        for (int c = 0; c < 4; ++c) {
            t_in[c] = near[c / 2][c % 2];
            t_out[c] = far[c / 2][c % 2];
        }
    }
};

/// The slab test of a build without run-time dispatch: four lanes when the
/// build's own target has AVX2 (-march=native, ZEROSET_NATIVE), else two pairs.
#if defined(__AVX2__)
using BuildSlabTest = FourLanes;
#else
using BuildSlabTest = TwoPairs;
#endif

}  // namespace

template <class Test>
[[gnu::always_inline]] inline void Bvh::walk(const Ray& ray, double t_min, double t_max, Visitor visit,
                                             void* context) const {
    if (order_.empty()) return;
    // A root node's own slab test finds its children: the root box, their
    // union, would only repeat it (with three divisions of its own). A
    // root leaf has no other test.
    double root_t = t_min;
    if (root_.count > 0) {
        const auto root_span = root_box_.clip(ray, t_min, t_max);
        if (!root_span) return;
        root_t = root_span->t0;
    }
    const auto inverse = [](double d) { return d != 0.0 ? 1.0 / d : std::copysign(1e300, d); };
    const RayInverse r{ray.origin, {inverse(ray.dir.x), inverse(ray.dir.y), inverse(ray.dir.z)}};
    // The nodes still to open and their entry t, in two arrays rather than
    // one of pairs: a pair written as two 8-byte stores and read back at
    // once as one 16-byte load (the nearest child, popped next) cannot be
    // forwarded from the store buffer, and that stall was a fifth of the
    // traversal. Each node visited pops one entry and pushes at most four
    // (and copies four, so the last push may write past its entries).
    constexpr std::size_t capacity = (width - 1) * max_depth + 2 + width;
    std::array<Child, capacity> pending;
    std::array<double, capacity> pending_t;
    std::size_t size = 0;
    pending[size] = root_;
    pending_t[size++] = root_t;
    while (size > 0) {
        --size;
        if (pending_t[size] > t_max) continue;
        const Child child = pending[size];
        if (child.count > 0) {
            for (std::uint32_t k = 0; k < child.count && t_max >= t_min; ++k)
                t_max = visit(context, order_[child.index + k], t_max);
            if (t_max < t_min) return;
            continue;
        }
        const Node& node = nodes_[child.index];
        double t_in[width], t_out[width];
        Test::run(node, r, t_min, t_max, t_in, t_out);
        // The children hit, farthest first onto the stack, so the nearest is on top.
        Child hit[width]{};
        double hit_t[width]{};
        int n = 0;
        for (int c = 0; c < width; ++c) {
            if (!(t_in[c] <= t_out[c]) || node.child[c].index == empty_slot) continue;
            int k = n++;
            for (; k > 0 && hit_t[k - 1] < t_in[c]; --k) {
                hit[k] = hit[k - 1];
                hit_t[k] = hit_t[k - 1];
            }
            hit[k] = node.child[c];
            hit_t[k] = t_in[c];
        }
        // All four copied whatever n is: a loop of n copies compiles to
        // `rep movs`, whose start-up cost was half the traversal's time.
        for (int k = 0; k < width; ++k) {
            pending[size + static_cast<std::size_t>(k)] = hit[k];
            pending_t[size + static_cast<std::size_t>(k)] = hit_t[k];
        }
        size += static_cast<std::size_t>(n);
    }
}

template <class Test>
[[gnu::always_inline]] inline void Bvh::walk_in_order(const Ray& ray, double t_min, double t_max, Queue& queue,
                                                      Visitor visit, void* context) const {
    queue.clear();
    const auto root_span = order_.empty() ? std::nullopt : root_box_.clip(ray, t_min, t_max);
    if (root_span) {
        const auto inverse = [](double d) { return d != 0.0 ? 1.0 / d : std::copysign(1e300, d); };
        const RayInverse r{ray.origin, {inverse(ray.dir.x), inverse(ray.dir.y), inverse(ray.dir.z)}};
        const auto later = [](const QueueEntry& a, const QueueEntry& b) { return a.t_enter > b.t_enter; };
        // The nearest child of the node just opened is usually the next
        // entry: it is taken at once, not pushed and popped, whenever no
        // queued entry comes before it.
        QueueEntry next{root_span->t0, root_.index, root_.count};
        bool has_next = true;
        while (has_next || !queue.empty()) {
            QueueEntry p = next;
            if (!has_next) {
                std::pop_heap(queue.begin(), queue.end(), later);
                p = queue.back();
                queue.pop_back();
            }
            has_next = false;
            if (p.t_enter > t_max) break;  // and so is every entry after it
            t_max = visit(context, frontier, p.t_enter);
            if (t_max < t_min) return;
            if (p.count > 0) {
                for (std::uint32_t k = 0; k < p.count && t_max >= t_min; ++k) t_max = visit(context, order_[p.index + k], t_max);
                if (t_max < t_min) return;
                continue;
            }
            const Node& node = nodes_[p.index];
            double t_in[width], t_out[width];
            Test::run(node, r, t_min, t_max, t_in, t_out);
            // One pass: each child met is queued unless it is the nearest so
            // far, and a nearest one displaced by a nearer is queued then.
            int nearest = -1;
            for (int c = 0; c < width; ++c) {
                if (!(t_in[c] <= t_out[c]) || node.child[c].index == empty_slot) continue;
                int queued = c;
                if (nearest < 0 || t_in[c] < t_in[nearest]) std::swap(queued, nearest);
                if (queued < 0) continue;
                queue.push_back({t_in[queued], node.child[queued].index, node.child[queued].count});
                std::push_heap(queue.begin(), queue.end(), later);
            }
            if (nearest >= 0) {
                const QueueEntry child{t_in[nearest], node.child[nearest].index, node.child[nearest].count};
                if (queue.empty() || !later(child, queue.front())) {
                    next = child;
                    has_next = true;
                } else {
                    queue.push_back(child);
                    std::push_heap(queue.begin(), queue.end(), later);
                }
            }
        }
    }
    visit(context, frontier, std::numeric_limits<double>::infinity());
}

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__)
__attribute__((target("arch=x86-64-v3"))) void Bvh::traverse_in_order_avx2(const Ray& ray, double t_min,
                                                                            double t_max, Queue& queue,
                                                                            Visitor visit, void* context) const {
    walk_in_order<FourLanes>(ray, t_min, t_max, queue, visit, context);
}

void Bvh::traverse_in_order(const Ray& ray, double t_min, double t_max, Queue& queue, Visitor visit,
                            void* context) const {
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) traverse_in_order_avx2(ray, t_min, t_max, queue, visit, context);
    else walk_in_order<TwoPairs>(ray, t_min, t_max, queue, visit, context);
}
#else
void Bvh::traverse_in_order(const Ray& ray, double t_min, double t_max, Queue& queue, Visitor visit,
                            void* context) const {
    walk_in_order<BuildSlabTest>(ray, t_min, t_max, queue, visit, context);
}
#endif

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__)
// The traversal compiled for AVX2 (x86-64-v3) as well, chosen by the CPU
// when it first runs: its four-lane slab test is about 1.3 times faster than
// two pairs on the sphere field of bench/bvh_bench.cpp, and the walk as a
// whole 2.2 times faster than the binary tree's was.
__attribute__((target("arch=x86-64-v3"))) void Bvh::traverse_avx2(const Ray& ray, double t_min, double t_max,
                                                                   Visitor visit, void* context) const {
    walk<FourLanes>(ray, t_min, t_max, visit, context);
}

void Bvh::traverse(const Ray& ray, double t_min, double t_max, Visitor visit, void* context) const {
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) traverse_avx2(ray, t_min, t_max, visit, context);
    else walk<TwoPairs>(ray, t_min, t_max, visit, context);
}
#else
void Bvh::traverse(const Ray& ray, double t_min, double t_max, Visitor visit, void* context) const {
    walk<BuildSlabTest>(ray, t_min, t_max, visit, context);
}
#endif

}  // namespace zeroset
