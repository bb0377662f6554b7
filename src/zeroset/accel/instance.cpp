// Rays in, hits out, through one affine map.
#include "zeroset/accel/instance.hpp"

#include <cmath>
#include <stdexcept>

#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

Instance::Instance(std::shared_ptr<const Primitive> child, const Mat4& to_parent, MaterialId material)
    : child_(std::move(child)), to_parent_(to_parent), material_(material), stretch_(to_parent.max_stretch()) {
    const std::optional<Mat4> inverse = to_parent.inverse();
    if (!inverse) throw std::invalid_argument("a transform must be invertible (a scale of 0 flattens the object)");
    to_child_ = *inverse;
    condition_ = 3.0 * stretch_ * to_child_.max_stretch();  // each norm within √3 of its longest column
    box_ = to_parent_.transform_box(child_->bounds());
    if (std::isfinite(child_->bounds().diagonal()) && !std::isfinite(box_.diagonal()))
        throw std::invalid_argument("its transforms move its bounds past what a double can hold (the diagonal "
                                    "of their box overflows); keep them within about ±5e307");
}

Ray Instance::to_child(const Ray& ray) const {
    return {to_child_.transform_point(ray.origin), to_child_.transform_vector(ray.dir)};
}

void Instance::lift(Hit& hit) const {
    SurfaceRef& s = hit.surface;
    // A leaf's own map is mostly the identity, and I·M is M exactly: no product.
    s.to_local = s.to_local.is_identity() ? to_child_ : s.to_local * to_child_;
    s.scale *= stretch_;
    if (s.material == no_material) s.material = material_;
}

std::optional<Hit> Instance::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    if (scratch.camera_frustum) return first_hit_in_tile(ray, t_min, t_max, scratch);
    std::optional<Hit> hit = child_->first_hit(to_child(ray), t_min, t_max, scratch);
    if (hit) lift(*hit);
    return hit;
}

CameraFrustum Instance::child_tile(const CameraFrustum& tile, TraceScratch& scratch) const {
    TraceScratch::ChildTile& slot = scratch.child_tile(this);
    if (slot.instance != this || tile.serial == 0 || slot.parent != tile.serial)
        slot = {this, tile.serial, tile.in_child_space(to_child_)};
    return slot.frustum;
}

bool Instance::misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const {
    if (tile.misses(box_)) return true;
    return condition_ <= well_conditioned && child_->misses_tile(child_tile(tile, scratch), scratch);
}

// Out of line, so that rays without a tile (most, in most scenes) pay nothing for it.
[[gnu::noinline]] std::optional<Hit> Instance::first_hit_in_tile(const Ray& ray, double t_min, double t_max,
                                                                 TraceScratch& scratch) const {
    // A camera ray's tile goes into the child's space with the ray.
    const CameraFrustum tile = child_tile(*scratch.camera_frustum, scratch);
    const CameraFrustumScope scope(scratch, &tile);
    std::optional<Hit> hit = child_->first_hit(to_child(ray), t_min, t_max, scratch);
    if (hit) lift(*hit);
    return hit;
}

bool Instance::occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    return child_->occluded(to_child(ray), t_min, t_max, scratch);
}

void Instance::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const std::size_t first = out.size();
    child_->spans(to_child(ray), t_min, t_max, scratch, out);
    for (std::size_t i = first; i < out.size(); ++i) {
        lift(out[i].enter);
        lift(out[i].exit);
    }
}

}  // namespace zeroset
