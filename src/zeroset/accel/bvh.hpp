// Bvh: a bounding-volume hierarchy over boxes (survey §6.1), so a ray meets
// only the objects whose bounds it enters, nearest first. Built top-down with
// the binned surface-area heuristic (Wald 2007): at each node, 16 bins of
// the primitives' centroids along each axis, the split of least expected
// cost. Subtrees of large inputs are built on all cores. Traversal keeps a
// fixed stack (the build bounds the depth) and visits boxes by entry
// distance, so a closest-hit query can shrink t_max as it goes.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/math/box3.hpp"

namespace zeroset {

class Bvh {
public:
    /// The deepest a tree gets: past depth 96 the build splits at the median,
    /// so 96 + log2(n) levels suffice for any n below 2^32.
    static constexpr std::size_t max_depth = 128;

    /// Builds over `boxes` (each bounded), using up to `threads` threads (0:
    /// all cores) for inputs large enough to gain from them.
    explicit Bvh(std::span<const Box3> boxes, int threads = 0);

    /// Calls `visit(i, t_max)` for the boxes i the ray enters within
    /// [t_min, t_max], nearest entry first; `visit` returns the new t_max (a
    /// hit makes it smaller; a value below t_min ends the traversal).
    template <class Visit>
    void traverse(const Ray& ray, double t_min, double t_max, Visit&& visit) const;

    [[nodiscard]] std::size_t node_count() const { return nodes_.size(); }
    [[nodiscard]] std::size_t depth() const { return depth_; }
    [[nodiscard]] bool empty() const { return order_.empty(); }

    struct BuildNode;  // the tree while it is built (bvh.cpp)

private:
    struct Node {
        Box3 box;
        std::uint32_t right_or_first;  // interior: the right child's index (the left is next); leaf: first in order_
        std::uint32_t count;           // 0 for an interior node
    };

    /// Where the ray is inside the box within [t_min, t_max], as an entry t, or +∞ if nowhere.
    static double entry(const Box3& box, const Vec3d& origin, const Vec3d& inverse_dir, double t_min, double t_max);
    void flatten(const BuildNode& node, std::size_t depth);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // box indices, leaf by leaf
    std::size_t depth_ = 0;
};

inline double Bvh::entry(const Box3& box, const Vec3d& origin, const Vec3d& inverse_dir, double t_min, double t_max) {
    for (int axis = 0; axis < 3; ++axis) {
        // A zero direction gives ±∞, or NaN on the slab's plane; the argument
        // order of min/max makes a NaN drop out.
        const double a = (box.lo[axis] - origin[axis]) * inverse_dir[axis];
        const double b = (box.hi[axis] - origin[axis]) * inverse_dir[axis];
        const double near = std::min(b, a), far = std::max(b, a);
        t_min = std::max(t_min, near);
        t_max = std::min(t_max, far * (1.0 + 4e-16));  // rounding of the slab distances
        if (t_min > t_max) return INFINITY;
    }
    return t_min;
}

template <class Visit>
void Bvh::traverse(const Ray& ray, double t_min, double t_max, Visit&& visit) const {
    if (nodes_.empty()) return;
    const Vec3d inverse_dir{1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z};
    struct Pending {
        std::uint32_t node;
        double t_enter;
    };
    std::array<Pending, max_depth + 1> stack;
    std::size_t size = 0;
    const double root = entry(nodes_[0].box, ray.origin, inverse_dir, t_min, t_max);
    if (root != INFINITY) stack[size++] = {0, root};
    while (size > 0) {
        const Pending p = stack[--size];
        if (p.t_enter > t_max) continue;
        const Node& node = nodes_[p.node];
        if (node.count > 0) {
            for (std::uint32_t k = 0; k < node.count && t_max >= t_min; ++k)
                t_max = visit(order_[node.right_or_first + k], t_max);
            if (t_max < t_min) return;
            continue;
        }
        const std::uint32_t left = p.node + 1, right = node.right_or_first;
        const double tl = entry(nodes_[left].box, ray.origin, inverse_dir, t_min, t_max);
        const double tr = entry(nodes_[right].box, ray.origin, inverse_dir, t_min, t_max);
        // The nearer child goes on top.
        if (tl <= tr) {
            if (tr != INFINITY) stack[size++] = {right, tr};
            if (tl != INFINITY) stack[size++] = {left, tl};
        } else {
            if (tl != INFINITY) stack[size++] = {left, tl};
            stack[size++] = {right, tr};
        }
    }
}

}  // namespace zeroset
