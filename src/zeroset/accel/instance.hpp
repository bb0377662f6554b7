// Instance: a shared child placed with its own affine transform and
// material (survey §9, eq. 36) — what an object's `translate`, `rotate`, …
// become, and how one prepared shape is placed many times without a copy of
// its tape. The ray is moved into the child's space, x_o' = M⁻¹x_o and
// x_d' = M⁻¹x_d, so t is the same on both sides; x_d' is generally not of
// unit length, which every method accounts for (RayFunction::dir_length).
// Normals come back through the inverse transpose (§8).
#pragma once

#include <memory>

#include "zeroset/accel/primitive.hpp"

namespace zeroset {

class Instance final : public Primitive {
public:
    /// `to_parent` maps the child's space into the instance's; it must be
    /// invertible (throws std::invalid_argument otherwise). `material` is
    /// given to the parts of the child that have none.
    Instance(std::shared_ptr<const Primitive> child, const Mat4& to_parent, MaterialId material);

    [[nodiscard]] Box3 bounds() const override { return box_; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    bool occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    /// The child asked with the tile in its space — unless the map is so far
    /// from a similarity that the tile's planes, carried there, would be
    /// off by more than the margins of the tests below (the condition
    /// number past `well_conditioned`): then only the box in this space.
    bool misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const override;
    /// POV-Ray's axes, cylinders scaled by 0.01 across, are at 100.
    static constexpr double well_conditioned = 1e3;

    [[nodiscard]] const Primitive& child() const { return *child_; }
    [[nodiscard]] const Mat4& to_parent() const { return to_parent_; }

private:
    [[nodiscard]] Ray to_child(const Ray& ray) const;
    /// The tile in the child's space: made once for the tile's rays, then
    /// copied from the scratch (a query below may reuse the slot while the
    /// caller's runs), so that it keeps its serial for the child's caches.
    [[nodiscard]] CameraFrustum child_tile(const CameraFrustum& tile, TraceScratch& scratch) const;
    /// first_hit() for a camera ray that comes with its tile (TraceScratch::camera_frustum).
    std::optional<Hit> first_hit_in_tile(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const;
    /// A hit in the child's terms, in the instance's.
    void lift(Hit& hit) const;

    std::shared_ptr<const Primitive> child_;
    Mat4 to_parent_;
    Mat4 to_child_;
    MaterialId material_;
    double stretch_;  // how much to_parent stretches lengths
    double condition_;  // at least the linear part's condition number, ‖A‖·‖A⁻¹‖ (within a factor of 3)
    Box3 box_;
};

}  // namespace zeroset
