// Nearest hit, any hit and span union over a BVH of children.
#include "zeroset/accel/group.hpp"

#include <algorithm>

#include "zeroset/accel/span_ops.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

namespace {

std::vector<std::shared_ptr<const Primitive>> bounded_first(std::vector<std::shared_ptr<const Primitive>> children) {
    std::stable_partition(children.begin(), children.end(), [](const auto& c) { return is_bounded(c->bounds()); });
    return children;
}

std::vector<Box3> boxes_of(const std::vector<std::shared_ptr<const Primitive>>& children, std::size_t bounded) {
    std::vector<Box3> boxes;
    boxes.reserve(bounded);
    for (std::size_t i = 0; i < bounded; ++i) boxes.push_back(children[i]->bounds());
    return boxes;
}

}  // namespace

Group::Group(std::vector<std::shared_ptr<const Primitive>> children, int threads)
    : children_(bounded_first(std::move(children))),
      bounded_(static_cast<std::size_t>(
          std::count_if(children_.begin(), children_.end(), [](const auto& c) { return is_bounded(c->bounds()); }))),
      bvh_(boxes_of(children_, bounded_), threads) {
    box_ = empty_box();
    for (const auto& child : children_) box_ = united(box_, child->bounds());
}

std::optional<Hit> Group::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    std::optional<Hit> best;
    const auto consider = [&](const Primitive& child, double limit) {
        if (std::optional<Hit> hit = child.first_hit(ray, t_min, limit, scratch); hit && (!best || hit->t < best->t)) {
            best = hit;
            return hit->t;
        }
        return limit;
    };
    for (std::size_t i = bounded_; i < children_.size(); ++i) t_max = consider(*children_[i], t_max);
    bvh_.traverse(ray, t_min, t_max, [&](std::uint32_t i, double limit) { return consider(*children_[i], limit); });
    return best;
}

bool Group::occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    // The child that blocked last time first (children's own queries may
    // reuse the cache's slot, so it is read once and written afresh).
    const TraceScratch::Occluder last = scratch.last_occluder(this);
    const std::uint32_t tried = last.group == this ? last.child : ~std::uint32_t{0};
    if (tried < children_.size() && children_[tried]->occluded(ray, t_min, t_max, scratch)) return true;
    const auto blocks = [&](std::uint32_t i) {
        if (i == tried || !children_[i]->occluded(ray, t_min, t_max, scratch)) return false;
        scratch.last_occluder(this) = {this, i};
        return true;
    };
    for (std::size_t i = bounded_; i < children_.size(); ++i)
        if (blocks(static_cast<std::uint32_t>(i))) return true;
    bool blocked = false;
    bvh_.traverse(ray, t_min, t_max, [&](std::uint32_t i, double limit) {
        blocked = blocks(i);
        return blocked ? -INFINITY : limit;
    });
    return blocked;
}

bool Group::misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const {
    const auto basis = tile.dual_basis();
    if (!basis) return false;
    const CameraFrustum::Planes planes = tile.planes(*basis);
    int asked = 0;
    const auto misses = [&](std::uint32_t i) {
        return ++asked <= children_asked_per_tile && children_[i]->misses_tile(tile, scratch);
    };
    for (std::size_t i = bounded_; i < children_.size(); ++i)
        if (!misses(static_cast<std::uint32_t>(i))) return false;
    bool missed = true;
    bvh_.select([&](const Box3& box) { return !tile.misses(box, planes); },
                [&](std::uint32_t i) { return missed = misses(i); });
    return missed;
}

void Group::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const TraceScratch::SpanLease all(scratch);
    for (std::size_t i = bounded_; i < children_.size(); ++i) children_[i]->spans(ray, t_min, t_max, scratch, *all);
    bvh_.traverse(ray, t_min, t_max, [&](std::uint32_t i, double limit) {
        children_[i]->spans(ray, t_min, limit, scratch, *all);
        return limit;
    });
    merge_overlapping(*all);
    out.insert(out.end(), all->begin(), all->end());
}

}  // namespace zeroset
