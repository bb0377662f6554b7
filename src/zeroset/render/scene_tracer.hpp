// SceneTracer: one render thread's view of a prepared scene — the nearest
// hit of a ray with its normal and material, and shadow-ray occlusion —
// over the scene's root primitive, with the thread's own scratch, so tracing
// never allocates (after warm-up) or locks.
#pragma once

#include <optional>
#include <string>

#include "zeroset/accel/trace_scratch.hpp"
#include "zeroset/render/prepared_scene.hpp"

namespace zeroset {

struct SurfaceHit {
    double t;
    Vec3d point;
    Vec3d local_point;  // the same point in the object's own space (for colour patterns)
    Vec3d normal;  // unit, facing the ray's origin
    MaterialId material;
    double scale;  // the size of the object hit (its shrunk bounds' diagonal), in scene units
};

class SceneTracer {
public:
    explicit SceneTracer(const PreparedScene& prepared);

    /// The nearest surface along the ray in [0, t_max]. A camera ray may
    /// come with its image tile and its pixel there (TraceScratch::camera_frustum).
    std::optional<SurfaceHit> closest_hit(const Ray& ray, double t_max, const CameraFrustum* tile = nullptr,
                                          int pixel = 0);
    /// True when some surface lies on the ray in [0, t_max].
    bool occluded(const Ray& ray, double t_max);
    /// True when no camera ray of the tile meets a surface, proven
    /// (Primitive::misses_tile).
    /// `rows_missed`: rows of the tile are traced and all missed
    /// (TraceScratch::tile_rows_missed).
    bool misses_tile(const CameraFrustum& tile, bool rows_missed) {
        scratch_.tile_rows_missed = rows_missed;
        const bool missed = prepared_->root().misses_tile(tile, scratch_);
        scratch_.tile_rows_missed = false;
        return missed;
    }
    /// The hit's diffuse colour: its material's, or its pattern's there.
    Vec3d albedo(const SurfaceHit& hit);

    [[nodiscard]] const PreparedScene& prepared() const { return *prepared_; }
    [[nodiscard]] TraceCounters& counters() { return scratch_.counters; }
    /// Where a surface first evaluated to NaN, if one did.
    [[nodiscard]] const std::optional<TraceScratch::NanRecord>& first_nan() const { return scratch_.first_nan; }

private:
    /// The unit normal in the scene's space, facing the ray.
    Vec3d normal_at(const SurfaceRef& surface, const Ray& ray);

    const PreparedScene* prepared_;
    TraceScratch scratch_;
    std::vector<ColorPatternEvaluator> patterns_;  // one for each distinct pattern of the scene
    std::vector<int> pattern_of_;                   // by MaterialId: its index in patterns_, or -1
};

/// "the surface of object 'NAME' evaluates to NaN at (x, y, z) — …": the
/// render error for a NaN met while tracing.
std::string nan_message(const TraceScratch::NanRecord& nan);

}  // namespace zeroset
