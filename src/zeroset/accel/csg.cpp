// Intersection and difference over span lists.
#include "zeroset/accel/csg.hpp"

#include <stdexcept>

#include "zeroset/accel/span_ops.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

CsgNode::CsgNode(Operation operation, std::vector<std::shared_ptr<const Primitive>> children)
    : operation_(operation), children_(std::move(children)) {
    if (children_.empty()) throw std::invalid_argument("a CSG node needs at least one child");
    box_ = children_.front()->bounds();
    if (operation_ == Operation::Intersection) {
        for (const auto& child : children_) {
            const Box3 b = child->bounds();
            box_ = overlap(box_, b);
        }
        if (!box_.valid()) box_ = {{0, 0, 0}, {0, 0, 0}};  // the children's boxes do not meet: empty
    }
}

std::optional<Hit> CsgNode::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    const TraceScratch::SpanLease result(scratch);
    spans(ray, t_min, t_max, scratch, *result);
    if (result->empty()) return std::nullopt;
    return result->front().enter;
}

void CsgNode::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const TraceScratch::SpanLease result(scratch), other(scratch), merged(scratch);
    children_.front()->spans(ray, t_min, t_max, scratch, *result);
    for (std::size_t i = 1; i < children_.size() && !result->empty(); ++i) {
        // Only where the result may still change.
        const double from = std::max(t_min, result->front().enter.t), to = std::min(t_max, result->back().exit.t);
        other->clear();
        children_[i]->spans(ray, from, to, scratch, *other);
        if (operation_ == Operation::Intersection) intersect(*result, *other, *merged);
        else subtract(*result, *other, *merged);
        std::swap(*result, *merged);
    }
    out.insert(out.end(), result->begin(), result->end());
}

}  // namespace zeroset
