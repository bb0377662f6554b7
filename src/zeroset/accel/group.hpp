// Group: children in a BVH (survey §6.1) — the scene's top level, a `group`
// or `union` block, a shape with several parts. A ray tests only the
// children whose bounds it enters, nearest first, and the closest hit
// shrinks the rest of the search. Children with unbounded bounds (no box
// can hold them) are kept out of the tree and tested on every ray. As a CSG
// operand a group is the union of its children (Roth: merged span lists).
#pragma once

#include <memory>
#include <vector>

#include "zeroset/accel/bvh.hpp"
#include "zeroset/accel/primitive.hpp"

namespace zeroset {

class Group final : public Primitive {
public:
    /// Builds the BVH with up to `threads` threads (0: all cores).
    explicit Group(std::vector<std::shared_ptr<const Primitive>> children, int threads = 0);

    [[nodiscard]] Box3 bounds() const override { return box_; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    bool occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    /// Every child the tile's frustum meets the box of misses the tile; false
    /// (not proven) past `children_asked_per_tile` such children.
    bool misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const override;
    static constexpr int children_asked_per_tile = 16;

    [[nodiscard]] const std::vector<std::shared_ptr<const Primitive>>& children() const { return children_; }
    [[nodiscard]] const Bvh& bvh() const { return bvh_; }

private:
    std::vector<std::shared_ptr<const Primitive>> children_;  // the bounded ones first, in BVH index order
    std::size_t bounded_ = 0;                                 // how many of them are bounded
    Bvh bvh_;
    Box3 box_;
};

}  // namespace zeroset
