// ConeTracer: antialiased sphere tracing (Hart, "Sphere tracing", 1993; the
// survey's [Hart, 1993], §5.2): one ray per pixel, widened to the cone of
// the pixel's footprint, whose radius grows as r(t) = κ·t (a disk of one
// pixel's area).
//
// The ray itself is traced first, as every ray is, so its first hit is
// guaranteed by its object's method. The cone then looks for silhouettes
// with the scene's distance bound (render/scene_distance.hpp):
//   - outer edges: from the eye to the hit, where d(t) < r(t) a surface
//     the ray misses passes through the cone; each stretch of t where it
//     does is one edge, taken where d/r is least;
//   - the inner edge: past the hit, along the chord through the solid, the
//     depth bound staying below r(t) over a chord far longer than it is
//     deep means the ray runs near the solid's silhouette.
// Hart blends an edge by the share of the disk the bound implies; a bound
// is a lower one, often loose, so here it only says where to look. Rays
// from the eye, aimed across the cone at the edge's surface and bisected,
// find where the surface really crosses the disk (to 1/32 of r), and the
// share beyond a straight edge there (disk_coverage) weights the colour
// the last ray past it sees — its own object's normal, material and
// shadows. Samples are composited front to back over what the ray sees:
// C = Σ (1 − A_i) α_i c_i + (1 − A) c_ray.
//
// Far from every surface, interval analysis over the cone's box passes
// whole stretches of t that hold no solid (Fig. 9, step 2).
//
// Steps are max(d, r/2), at least a millionth of the scene's size, so t
// grows at least geometrically and each march ends; it stops, keeping what
// it found, after max_steps. The outer march never passes the ray's hit,
// so the antialiasing never changes which surface a pixel's centre sees.
// Not antialiased: shadow edges, reflections, and surfaces beyond the box
// of the bounded objects (an infinite plane's horizon).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "zeroset/accel/bvh.hpp"
#include "zeroset/render/render_stats.hpp"
#include "zeroset/render/scene_distance.hpp"
#include "zeroset/render/scene_tracer.hpp"
#include "zeroset/render/shading.hpp"

namespace zeroset {

/// The share of a disk of radius 1 beyond a straight line at distance u
/// from its centre: ½ at u = 0, 0 for u ≥ 1, 1 for u ≤ −1.
double disk_coverage(double u);

class ConeTracer {
public:
    /// The steps one cone may take before it stops.
    static constexpr int max_steps = 4096;
    /// Edge samples one pixel may blend; further ones are not looked for.
    static constexpr int max_edges = 8;
    /// Bisections of an edge's place across the disk: to 1/32 of the
    /// cone's radius at worst.
    static constexpr int edge_refinements = 4;

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
        double t_far = 0.0;  // an aimed ray that meets a surface before this meets the edge's
        DistanceBound bound;
    };
    /// What an edge shows and the share of the disk it shows it in.
    struct EdgeSample {
        Vec3d color;
        double coverage;
    };
    /// Where along the ray each top-level node can come within the cone:
    /// its box grown by the cone's radius, clipped to span; sorted by start.
    void find_windows(const Ray& ray, const Span& span);
    /// The top-level nodes' boxes grown for cones from `eye`, and a BVH over
    /// them (all camera rays share the eye, so this is done once).
    void grow_boxes(const Vec3d& eye);
    /// candidates_: the roots whose windows hold t.
    void candidates_at(double t);
    /// The edges along the ray up to t_end, nearest first; returns how many.
    int find_edges(const Ray& ray, double t_end, bool ends_on_hit, ConeCounters& counters);
    /// Where the chord of the ray through the solid it hits at t_hit (with
    /// that normal) lies least deep, when that is less than the cone's
    /// radius: the cone there reaches past the solid's silhouette.
    std::optional<Edge> find_inner_edge(const Ray& ray, double t_hit, const Vec3d& normal, ConeCounters& counters);
    /// The unit direction across the cone (perpendicular to the ray) in
    /// which the edge's surface lies (an outer edge) or ends (an inner one):
    /// down the distance bound's differences across the disk.
    std::optional<Vec3d> across_edge(const Ray& ray, const Edge& edge);
    /// Where the edge's surface crosses the cone's disk, found by rays from
    /// the eye aimed across it and bisected (edge_refinements times), and
    /// the colour past it; nothing when no surface reaches into the cone.
    std::optional<EdgeSample> resolve(SceneTracer& tracer, const Ray& ray, const Edge& edge, ShadingCounters& shading,
                                      int bounces, ConeCounters& counters);

    const SceneDistance* distance_;
    DistanceProbe probe_;
    double footprint_;
    double least_step_;
    std::array<Edge, max_edges> edges_{};
    struct Window {
        Span span;
        int root;
    };
    std::vector<Box3> grown_;  // by top-level node, for cones from grown_for_
    Vec3d grown_for_{};
    std::vector<int> bounded_, unbounded_;  // the roots with bounded grown boxes (the BVH's, in its order) and the rest
    std::optional<Bvh> bvh_;
    std::vector<int> candidates_;  // the roots an edge's distance bounds look at
    std::vector<Window> windows_;
    std::vector<std::size_t> open_;  // the windows begun and not yet ended, in windows_
    std::vector<int> active_;        // their roots
};

}  // namespace zeroset
