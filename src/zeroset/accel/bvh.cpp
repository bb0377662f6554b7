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

Box3 empty_box() { return {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}; }
Box3 unite(const Box3& a, const Box3& b) { return {min(a.lo, b.lo), max(a.hi, b.hi)}; }
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
            const int b = static_cast<int>(bin_count * ((item.centroid[axis] - lo) / extent));
            return std::clamp(b, 0, bin_count - 1);
        };
        for (const Item& item : items) {
            const int b = bin_of(item);
            bin_box[b] = unite(bin_box[b], item.box);
            ++bin_items[b];
        }
        // Sweep from the right for the right-hand sides' areas, then from the left.
        std::array<double, bin_count> right_cost{};
        Box3 right = empty_box();
        std::size_t right_count = 0;
        for (int b = bin_count - 1; b > 0; --b) {
            right = unite(right, bin_box[b]);
            right_count += bin_items[b];
            right_cost[b] = half_area(right) * static_cast<double>(right_count);
        }
        Box3 left = empty_box();
        std::size_t left_count = 0;
        for (int b = 0; b < bin_count - 1; ++b) {
            left = unite(left, bin_box[b]);
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
        box = unite(box, item.box);
        centroids = unite(centroids, {item.centroid, item.centroid});
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
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    const BuildNode* const children[2] = {node.left.get(), node.right.get()};
    for (int c = 0; c < 2; ++c) {
        Node& n = nodes_[index];  // (re)taken: the recursion below may grow nodes_
        for (int axis = 0; axis < 3; ++axis) {
            n.lo[axis][static_cast<std::size_t>(c)] = round_down(children[c]->box.lo[axis]);
            n.hi[axis][static_cast<std::size_t>(c)] = round_up(children[c]->box.hi[axis]);
        }
        const Child child = child_of(*children[c], depth + 1);
        nodes_[index].child[c] = child;
    }
    return index;
}

}  // namespace zeroset
