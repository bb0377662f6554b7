// HalfSpace: the solid n·p + c ≤ 0 — an object whose surface is a plane
// (degree 1 in x, y, z) and that has no bounds: the floor of a scene, an
// endless wall. No bounds means no finite span for a root finder to search,
// but a plane needs none: along a ray f is linear, t = −f(x_o)/(n·x_d).
// The group it is in keeps it out of its BVH and tests it on every ray.
#pragma once

#include <string>

#include "zeroset/accel/primitive.hpp"
#include "zeroset/expr/expr.hpp"

namespace zeroset {

class HalfSpace final : public LeafPrimitive {
public:
    /// `f` must be of degree 1 with a nonzero gradient (throws
    /// std::invalid_argument otherwise).
    HalfSpace(std::string name, const Expr& f, MaterialId material);

    [[nodiscard]] Box3 bounds() const override;
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const override;
    [[nodiscard]] const std::string& name() const override { return name_; }

    [[nodiscard]] const Vec3d& normal() const { return n_; }
    [[nodiscard]] double offset() const { return c_; }

private:
    [[nodiscard]] Hit boundary(const Ray& ray, double t, BoundaryKind kind) const;

    std::string name_;
    Vec3d n_;   // ∇f, constant
    double c_;  // f(0, 0, 0)
    MaterialId material_;
};

}  // namespace zeroset
