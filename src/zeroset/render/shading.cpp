// Blinn–Phong: ambient + Σ over visible lights (diffuse + specular), plus
// the mirror image for a reflective material, traced recursively.
#include "zeroset/render/shading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "zeroset/math/scalar.hpp"

namespace zeroset {

namespace {

/// Shadow rays start a little off the surface along the normal, far enough
/// that the surface just hit is not found again (its hit tolerance is
/// relative to the object's size, see trace/root_finder.hpp).
double shadow_offset(const SurfaceHit& hit) { return 1e-4 * hit.scale; }

}  // namespace

Vec3d shade(SceneTracer& tracer, const Ray& ray, const SurfaceHit& hit, ShadingCounters& shading, int bounces_left) {
    const Material& m = tracer.prepared().material(hit.material);
    const Vec3d albedo = tracer.albedo(hit);
    Vec3d color = hadamard(tracer.prepared().scene().ambient, albedo) * m.ambient;
    const Vec3d origin = hit.point + hit.normal * shadow_offset(hit);
    for (const Light& light : tracer.prepared().lights()) {
        Vec3d to_light;
        double distance = std::numeric_limits<double>::infinity();
        if (light.kind == Light::Kind::Point) {
            to_light = light.position - hit.point;
            distance = length(to_light);
            if (!(distance > 0.0)) continue;  // the light is at the point itself: no direction to it
            to_light = to_light / distance;
        } else {
            to_light = -normalize(light.direction);
        }
        const double lambert = dot(hit.normal, to_light);
        if (lambert <= 0.0) continue;
        if (light.casts_shadows) {
            ++shading.shadow_rays;
            if (tracer.occluded({origin, to_light}, distance)) continue;
        }
        const Vec3d half = normalize(to_light - ray.dir);
        const double cosine = dot(hit.normal, half);
        double specular = 0.0;
        if (m.specular > 0.0 && cosine > 0.0) {
            const auto n = integer_value(m.shininess);  // the usual case: repeated squaring, not libm's pow
            specular = n ? powi(cosine, *n) : std::pow(cosine, m.shininess);
        }
        color += hadamard(light.color, albedo * (m.diffuse * lambert) + Vec3d{1, 1, 1} * (m.specular * specular));
    }
    if (m.reflection > 0.0 && bounces_left > 0) {
        ++shading.reflection_rays;
        const Ray mirror{origin, ray.dir - hit.normal * (2.0 * dot(ray.dir, hit.normal))};
        const auto seen = tracer.closest_hit(mirror, std::numeric_limits<double>::infinity());
        color += (seen ? shade(tracer, mirror, *seen, shading, bounces_left - 1) : tracer.prepared().scene().background) *
                 m.reflection;
    }
    return color;
}

}  // namespace zeroset
