// SweptSphere: one segment of a sweep — a sphere swept along a Bézier curve
// with a linearly varying radius (van Wijk 1984, survey §3.4) — as a leaf
// primitive. Its spans along a ray are exact (trace/swept_sphere.hpp): the
// roots of polynomials in the curve parameter, by Descartes' rule of signs,
// with no step size or Lipschitz bound. A sweep of several segments is a group
// of these, so its BVH tests a ray only against the segments it comes near,
// and the union of their spans joins them.
//
// The normal at a hit is that of the sphere the point lies on (the envelope
// touches it there), found again from the point (sphere_through), so a hit
// carries nothing but its point.
#pragma once

#include <string>

#include "zeroset/accel/primitive.hpp"
#include "zeroset/trace/swept_sphere.hpp"

namespace zeroset {

class SweptSphere final : public LeafPrimitive {
public:
    SweptSphere(std::string name, const SweptSegment& segment, MaterialId material);

    [[nodiscard]] Box3 bounds() const override { return bounds_; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const override;
    [[nodiscard]] const std::string& name() const override { return name_; }

    [[nodiscard]] const SweptSegment& segment() const { return segment_; }

private:
    /// The exact spans, counted, if the ray comes within the segment's box.
    [[nodiscard]] SweepSpans exact_spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const;
    [[nodiscard]] Hit boundary(const Ray& ray, double t, BoundaryKind kind) const;

    std::string name_;
    SweptSegment segment_;
    MaterialId material_;
    Box3 bounds_;
};

}  // namespace zeroset
