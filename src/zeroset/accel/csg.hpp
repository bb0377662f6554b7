// CsgNode: the intersection of its children, or the first child minus the
// rest, by merging span lists (survey §7; Roth 1982). Each child may be
// traced by its own method — a polynomial torus minus an interval-traced
// gyroid minus a sphere-traced model — since a span list is all a child has
// to give. Later children are asked only over the part of the ray where
// the result so far is not empty. (CSG union is a Group.)
#pragma once

#include <memory>
#include <vector>

#include "zeroset/accel/primitive.hpp"

namespace zeroset {

class CsgNode final : public Primitive {
public:
    enum class Operation { Intersection, Difference };

    /// At least one child; throws std::invalid_argument otherwise.
    CsgNode(Operation operation, std::vector<std::shared_ptr<const Primitive>> children);

    [[nodiscard]] Box3 bounds() const override { return box_; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;

    [[nodiscard]] Operation operation() const { return operation_; }

private:
    Operation operation_;
    std::vector<std::shared_ptr<const Primitive>> children_;
    Box3 box_;
};

}  // namespace zeroset
