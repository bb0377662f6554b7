// Bvh: a bounding-volume hierarchy over boxes (survey §6.1), so a ray meets
// only the objects whose bounds it enters, nearest first. Built top-down with
// the binned surface-area heuristic (Wald 2007): at each node, 16 bins of
// the primitives' centroids along each axis, the split of least expected
// cost. Subtrees of large inputs are built on all cores. The binary tree is
// then collapsed into nodes of four children (each node takes the largest of
// its grandchildren in), whose boxes a ray tests together, four lanes at
// once — half the nodes to visit and far fewer unpredictable branches than a
// binary tree. Traversal keeps a fixed stack (the build bounds the depth) and
// visits boxes by entry distance, so a closest-hit query can shrink t_max as
// it goes.
#pragma once

#include <array>
#include <type_traits>
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
    void traverse(const Ray& ray, double t_min, double t_max, Visit&& visit) const {
        using V = std::remove_reference_t<Visit>;
        traverse(ray, t_min, t_max, [](void* f, std::uint32_t i, double t) { return (*static_cast<V*>(f))(i, t); },
                 static_cast<void*>(&visit));
    }

    /// The same with the visitor as a function and its context: the one
    /// traversal, compiled for AVX2 as well as for plain x86-64 and chosen
    /// by the CPU (bvh.cpp).
    using Visitor = double (*)(void* context, std::uint32_t index, double t_max);
    void traverse(const Ray& ray, double t_min, double t_max, Visitor visit, void* context) const;

    /// The nodes an in-order traversal still has to open, by entry t: the
    /// caller's, so that a traversal allocates nothing once it has grown.
    struct QueueEntry {
        double t_enter;
        std::uint32_t index;
        std::uint32_t count;
    };
    using Queue = std::vector<QueueEntry>;
    /// The index traverse_in_order's visitor gets with a frontier.
    static constexpr std::uint32_t frontier = ~std::uint32_t{0};

    /// Visits the boxes the ray enters within [t_min, t_max] in the order of
    /// their nodes' entry, nearest first, over a priority queue. Before each
    /// node is opened, `visit(frontier, t)` says that every box not visited
    /// yet enters at t or later (t = +∞ at the end), so that what lies before
    /// t is complete; `visit(i, t_max)` visits box i. Both return the new
    /// t_max (a value below t_min ends the traversal).
    template <class Visit>
    void traverse_in_order(const Ray& ray, double t_min, double t_max, Queue& queue, Visit&& visit) const {
        using V = std::remove_reference_t<Visit>;
        traverse_in_order(
            ray, t_min, t_max, queue, [](void* f, std::uint32_t i, double t) { return (*static_cast<V*>(f))(i, t); },
            static_cast<void*>(&visit));
    }
    void traverse_in_order(const Ray& ray, double t_min, double t_max, Queue& queue, Visitor visit,
                           void* context) const;

    /// Calls visit(i) for the boxes i of every leaf whose bounds `keep`
    /// accepts, skipping the subtrees whose bounds it rejects: a culling
    /// query (a camera tile's frustum). `keep(const Box3&)` must accept any
    /// box that holds one it accepts; `visit` returns false to stop.
    template <class Keep, class Visit>
    void select(Keep&& keep, Visit&& visit) const {
        if (order_.empty() || !keep(root_box_)) return;
        std::array<Child, width * max_depth> pending;  // each level adds at most width − 1 to what it takes
        std::size_t size = 0;
        pending[size++] = root_;
        while (size > 0) {
            const Child c = pending[--size];
            if (c.count > 0) {
                for (std::uint32_t k = 0; k < c.count; ++k)
                    if (!visit(order_[c.index + k])) return;
                continue;
            }
            const Node& node = nodes_[c.index];
            for (int k = width; k-- > 0;) {  // the first child on top
                if (node.child[k].index == empty_slot) continue;
                const Box3 box{{node.lo[0][k], node.lo[1][k], node.lo[2][k]}, {node.hi[0][k], node.hi[1][k], node.hi[2][k]}};
                if (keep(box)) pending[size++] = node.child[k];
            }
        }
    }

    [[nodiscard]] std::size_t node_count() const { return nodes_.size(); }
    [[nodiscard]] std::size_t depth() const { return depth_; }
    [[nodiscard]] bool empty() const { return order_.empty(); }

    struct BuildNode;  // the tree while it is built (bvh.cpp)

private:
    static constexpr int width = 4;  // children per node

    /// Where a child of a node leads.
    struct Child {
        std::uint32_t index;  // an interior node, or the first of `count` boxes in order_
        std::uint32_t count;  // 0 for an interior node
    };
    static constexpr std::uint32_t empty_slot = ~std::uint32_t{0};  // the index of a node's unused child
    /// Four children's boxes (floats rounded outward: 128 bytes a node) and where they lead.
    struct Node {
        std::array<float, width> lo[3];  // lo[axis][child]
        std::array<float, width> hi[3];
        Child child[width];
    };

    /// Adds the node for a build node's children (and grandchildren); returns its index.
    std::uint32_t flatten(const BuildNode& node, std::size_t depth);
    template <class SlabTest>
    void walk(const Ray& ray, double t_min, double t_max, Visitor visit, void* context) const;
    void traverse_avx2(const Ray& ray, double t_min, double t_max, Visitor visit, void* context) const;
    template <class SlabTest>
    void walk_in_order(const Ray& ray, double t_min, double t_max, Queue& queue, Visitor visit, void* context) const;
    void traverse_in_order_avx2(const Ray& ray, double t_min, double t_max, Queue& queue, Visitor visit,
                                void* context) const;
    [[nodiscard]] Child child_of(const BuildNode& node, std::size_t depth);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // box indices, leaf by leaf
    Child root_{0, 0};                  // the whole tree: a node, or a leaf when the build made no split
    Box3 root_box_{};
    std::size_t depth_ = 0;
};

}  // namespace zeroset
