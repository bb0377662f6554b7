// ConeTracer: antialiased sphere tracing (Hart, "Sphere tracing", 1993; the
// survey's [Hart, 1993], §5.2): one ray per pixel, widened to the cone of
// the pixel's footprint, whose radius grows as r(t) = κ·t.
//
// The ray itself is traced first, as every ray is (its first hit is
// guaranteed by the object's method). The cone then marches from the eye to
// that hit with the scene's distance bound d(t) (render/scene_distance.hpp).
// Where d(t) < r(t), a surface the ray misses passes through the cone: a
// silhouette. Each stretch of t where it does gives one edge sample at its
// narrowest point, covering the share α of the pixel that a straight edge
// at distance d from the centre cuts from a disk of radius r (disk_coverage).
// The edge is shaded by a ray aimed from the eye at the covered part of the
// disk, so that it gets its own object's normal, material and shadows; the
// samples are composited front to back, and the ray's own colour fills what
// they leave: C = Σ (1 − A_i) α_i c_i + (1 − A) c_ray.
//
// As in Hart's method, the edge is blended on its outer side only: a pixel
// whose centre ray hits is covered by that surface in full.
//
// Steps are max(d, r/2), at least a millionth of the scene's size, so t
// grows at least geometrically and the march ends; it stops, keeping what
// it found, after max_steps. Steps beyond the ray's first hit are never
// taken, so the antialiasing never changes which surface a pixel's centre
// sees.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "zeroset/render/scene_distance.hpp"
#include "zeroset/render/scene_tracer.hpp"
#include "zeroset/render/shading.hpp"

namespace zeroset {

/// The share of a disk of radius 1 beyond a straight line at distance u
/// from its centre: ½ at u = 0, 0 for u ≥ 1, 1 for u ≤ −1.
double disk_coverage(double u);

struct ConeCounters {
    std::uint64_t steps = 0;         // distance bounds taken along cones
    std::uint64_t edges = 0;         // edge samples shaded
    std::uint64_t missed_edges = 0;  // edges whose aimed ray found no surface (not blended)
    std::uint64_t gave_up = 0;       // cones stopped at max_steps
    std::uint64_t evaluations = 0;   // of the distance bounds
};

class ConeTracer {
public:
    /// The steps one cone may take before it stops.
    static constexpr int max_steps = 4096;
    /// Edge samples one pixel may blend; further ones are not looked for.
    static constexpr int max_edges = 8;

    /// `footprint`: the cone's radius per unit of t along a ray.
    ConeTracer(const SceneDistance& distance, double footprint);

    /// The pixel's colour: the edges the cone around `ray` passes on its way
    /// to `hit` (or through the scene, when it hits nothing) blended over
    /// `ray_color`, what the ray itself sees.
    Vec3d pixel(SceneTracer& tracer, const Ray& ray, const std::optional<SurfaceHit>& hit, const Vec3d& ray_color,
                ShadingCounters& shading, int bounces, ConeCounters& counters);

private:
    /// Where a cone came nearest to a surface it does not meet.
    struct Edge {
        double t = 0.0;
        double ratio = 1.0;  // d / r there
        double radius = 0.0;
        DistanceBound bound;
    };
    /// The edges along the ray up to t_end, nearest first; returns how many.
    int find_edges(const Ray& ray, double t_end, bool ends_on_hit, ConeCounters& counters);
    /// Where the chord of the ray through the solid it hits at t_hit lies
    /// least deep, when that is less than the cone's radius: the cone there
    /// reaches past the solid's silhouette.
    std::optional<Edge> find_inner_edge(const Ray& ray, double t_hit, ConeCounters& counters);
    /// The colour a ray from the eye sees when aimed across the edge's
    /// surface (past it, for an inner edge), if it finds what is there.
    std::optional<Vec3d> shade_aimed(SceneTracer& tracer, const Ray& ray, const Edge& edge, ShadingCounters& shading,
                                     int bounces);

    const SceneDistance* distance_;
    DistanceProbe probe_;
    double footprint_;
    double least_step_;
    std::array<Edge, max_edges> edges_{};
};

}  // namespace zeroset
