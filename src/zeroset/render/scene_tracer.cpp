// Nearest hit over the root primitive, with the normal of the leaf that owns
// the boundary brought back to the scene's space (eq. 36; §8).
#include "zeroset/render/scene_tracer.hpp"

#include <sstream>
#include <unordered_map>

namespace zeroset {

SceneTracer::SceneTracer(const PreparedScene& prepared)
    : prepared_(&prepared), scratch_(prepared.leaves().size()) {
    std::unordered_map<const ColorPatternTapes*, int> index;
    for (const auto& pattern : prepared.color_patterns()) {
        if (!pattern) {
            pattern_of_.push_back(-1);
            continue;
        }
        const auto [it, fresh] = index.emplace(pattern.get(), static_cast<int>(patterns_.size()));
        if (fresh) patterns_.emplace_back(*pattern);
        pattern_of_.push_back(it->second);
    }
}

Vec3d SceneTracer::albedo(const SurfaceHit& hit) {
    if (hit.material != no_material) {
        const int pattern = pattern_of_[static_cast<std::size_t>(hit.material)];
        if (pattern >= 0) return patterns_[static_cast<std::size_t>(pattern)](hit.local_point);
    }
    return prepared_->material(hit.material).color;
}

/// The leaf's outward normal (flipped for a subtracted solid's surface),
/// brought to the scene's space — and then turned to face the ray, since
/// Blinn–Phong shades both sides of a surface alike.
Vec3d SceneTracer::normal_at(const SurfaceRef& surface, const Ray& ray) {
    Vec3d n;
    if (surface.leaf) {
        n = surface.to_local.transpose_transform_vector(surface.leaf->local_normal(surface, scratch_));
        if (surface.flipped) n = -n;
    }
    const double len = length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return -normalize(ray.dir);  // no usable normal (the ray starts inside)
    n = n / len;
    return dot(n, ray.dir) > 0.0 ? -n : n;
}

std::optional<SurfaceHit> SceneTracer::closest_hit(const Ray& ray, double t_max, const CameraFrustum* tile,
                                                   int pixel) {
    // Made in place (a Hit is large): the tile is set for the query only.
    const std::optional<Hit> hit = [&] {
        const CameraFrustumScope scope(scratch_, tile);
        scratch_.camera_pixel = pixel;
        return prepared_->root().first_hit(ray, 0.0, t_max, scratch_);
    }();
    if (!hit) return std::nullopt;
    const Vec3d point = ray.at(hit->t);
    return SurfaceHit{hit->t, point, hit->surface.to_local.transform_point(point), normal_at(hit->surface, ray),
                      hit->surface.material, hit->surface.scale};
}

bool SceneTracer::occluded(const Ray& ray, double t_max) { return prepared_->root().occluded(ray, 0.0, t_max, scratch_); }

std::string nan_message(const TraceScratch::NanRecord& nan) {
    std::ostringstream message;
    message.precision(6);
    message << "the surface of object '" << nan.leaf->name() << "' evaluates to NaN at (" << nan.point.x << ", "
            << nan.point.y << ", " << nan.point.z
            << ") (in the object's own coordinates, before its transforms) — a function outside its domain there (sqrt or log of a negative number, 0/0, ∞ − ∞ after an overflow, …); "
               "fix the expression or tighten the bounds";
    return message.str();
}

}  // namespace zeroset
