// Bvh: a bounding-volume hierarchy over boxes (survey §6.1), so a ray meets
// only the objects whose bounds it enters, nearest first. Built top-down with
// the binned surface-area heuristic (Wald 2007): at each node, 16 bins of
// the primitives' centroids along each axis, the split of least expected
// cost. Subtrees of large inputs are built on all cores. Traversal keeps a
// fixed stack (the build bounds the depth) and visits boxes by entry
// distance, so a closest-hit query can shrink t_max as it goes.
#pragma once

#include <array>
#include <cmath>
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
    /// A child of a node: its box (floats rounded outward, so a node with
    /// both children's boxes fits one cache line) and where it leads.
    struct Child {
        std::uint32_t index;  // an interior node, or the first of `count` boxes in order_
        std::uint32_t count;  // 0 for an interior node
    };
    struct Node {
        std::array<float, 2> lo[3];  // lo[axis][child]
        std::array<float, 2> hi[3];
        Child child[2];
    };
    /// What a traversal needs of its ray: origin and 1/x_d, with a zero
    /// component's inverse huge but finite, so 0 · (1/x_d) is never NaN.
    struct RayInverse {
        Vec3d origin;
        Vec3d inverse;
    };

    /// Where the ray enters each child of the node within [t_min, t_max]; +∞ for a child it misses.
    static std::array<double, 2> entries(const Node& node, const RayInverse& ray, double t_min, double t_max);
    /// Adds the node for a build node's children; returns its index.
    std::uint32_t flatten(const BuildNode& node, std::size_t depth);
    [[nodiscard]] Child child_of(const BuildNode& node, std::size_t depth);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // box indices, leaf by leaf
    Child root_{0, 0};                  // the whole tree: a node, or a leaf when the build made no split
    Box3 root_box_{};
    std::size_t depth_ = 0;
};

inline std::array<double, 2> Bvh::entries(const Node& node, const RayInverse& ray, double t_min, double t_max) {
    // Both children at once, in one register of two doubles (a GCC/Clang
    // vector extension: SSE2 on x86-64, NEON on ARM).
    using Pair = double __attribute__((vector_size(16)));
    Pair near = {t_min, t_min}, far = {t_max, t_max};
    for (int axis = 0; axis < 3; ++axis) {
        const Pair lo = {node.lo[axis][0], node.lo[axis][1]}, hi = {node.hi[axis][0], node.hi[axis][1]};
        const double o = ray.origin[axis], inverse = ray.inverse[axis];
        const Pair a = (lo - o) * inverse, b = (hi - o) * inverse;
        const Pair entry = a < b ? a : b, exit = (a < b ? b : a) * (1.0 + 4e-16);  // rounding of the slab distances
        near = near < entry ? entry : near;
        far = exit < far ? exit : far;
    }
    return {near[0] <= far[0] ? near[0] : INFINITY, near[1] <= far[1] ? near[1] : INFINITY};
}

template <class Visit>
void Bvh::traverse(const Ray& ray, double t_min, double t_max, Visit&& visit) const {
    if (order_.empty()) return;
    const auto root_span = root_box_.clip(ray, t_min, t_max);
    if (!root_span) return;
    if (root_.count > 0) {
        for (std::uint32_t k = 0; k < root_.count && t_max >= t_min; ++k) t_max = visit(order_[root_.index + k], t_max);
        return;
    }
    const auto inverse = [](double d) { return d != 0.0 ? 1.0 / d : std::copysign(1e300, d); };
    const RayInverse r{ray.origin, {inverse(ray.dir.x), inverse(ray.dir.y), inverse(ray.dir.z)}};
    struct Pending {
        std::uint32_t node;
        double t_enter;
    };
    std::array<Pending, max_depth + 1> stack;
    std::size_t size = 0;
    stack[size++] = {root_.index, root_span->t0};
    while (size > 0) {
        const Pending p = stack[--size];
        if (p.t_enter > t_max) continue;
        const Node& node = nodes_[p.node];
        const std::array<double, 2> t = entries(node, r, t_min, t_max);
        // The nearer child first: a leaf is visited now, an interior node
        // goes on the stack (the nearer one on top).
        const int first = t[1] < t[0] ? 1 : 0;
        for (int pass = 1; pass >= 0; --pass) {  // the farther interior child is pushed first
            const int c = pass == 1 ? 1 - first : first;
            if (t[c] == INFINITY || node.child[c].count > 0) continue;
            stack[size++] = {node.child[c].index, t[c]};
        }
        for (int pass = 0; pass < 2; ++pass) {
            const int c = pass == 0 ? first : 1 - first;
            const Child& leaf = node.child[c];
            if (leaf.count == 0 || t[c] > t_max) continue;
            for (std::uint32_t k = 0; k < leaf.count && t_max >= t_min; ++k) t_max = visit(order_[leaf.index + k], t_max);
            if (t_max < t_min) return;
        }
    }
}

}  // namespace zeroset
