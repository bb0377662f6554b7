// Shading: Blinn–Phong with shadows and mirror reflection. Point lights are not attenuated with
// distance (as in POV-Ray's default), so a scene's look does not depend on
// its scale.
#pragma once

#include "zeroset/render/scene_tracer.hpp"

namespace zeroset {

struct ShadingCounters {
    std::uint64_t shadow_rays = 0;
    std::uint64_t reflection_rays = 0;
};

/// Linear RGB leaving the hit point towards the ray's origin; a reflective
/// material adds what its mirror ray sees, for up to `bounces_left` more
/// bounces (past them, nothing: black).
Vec3d shade(SceneTracer& tracer, const Ray& ray, const SurfaceHit& hit, ShadingCounters& shading, int bounces_left);

}  // namespace zeroset
