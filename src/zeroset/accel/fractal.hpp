// Fractal: a deterministic 3-D fractal as a primitive, sphere traced by its
// distance estimate (trace/fractal_estimate.hpp) as Hart, Sandin and
// Kauffman (1989) did — the method the survey's §5.2 and Fig. 12 grew from.
//
// Along a ray, from where it enters the set's bounding ball, each step is
// the estimate d at the current point: the ball of radius d about it holds
// none of the set, so the step cannot pass the surface (to the estimate's
// accuracy: see fractal_estimate.hpp). A hit is where d drops below the hit
// tolerance ε — the fractal has detail at every scale, so the surface drawn
// is the set grown by ε. ε is tied to the pixel footprint: `detail` times
// the footprint's radius at the point's distance from the ray's origin (the
// eye, for camera rays), never less than 10⁻⁶ of the bounding radius.
// Normals are central differences of the estimate (the survey's §8,
// eq. 34) over half the estimate at the hit, so they are smooth at the
// pixel's scale.
//
// Inside the set there is no estimate: a span's exit is found by sampling
// along the ray — steps of ε, or of 1/512 of the ball's chord when that is
// longer — and bisecting the last step down to ε, so an outside gap thinner
// than the step, inside the solid, can be missed by CSG. Each query takes
// at most 4096 estimate steps; past them it gives up (a failed query,
// counted, answered "no hit").
#pragma once

#include <memory>
#include <string>

#include "zeroset/accel/primitive.hpp"
#include "zeroset/trace/fractal_estimate.hpp"

namespace zeroset {

struct FractalDescription {
    std::string name;  // for messages
    std::shared_ptr<const FractalEstimate> estimate;
    MaterialId material = no_material;
    /// The pixel footprint's radius per unit of distance from a ray's
    /// origin (CameraRays::footprint_radius); 0 when there is no camera:
    /// then ε is 10⁻⁴ of the bounding radius.
    double footprint = 0.0;
    /// The hit tolerance in footprints (> 0): smaller shows finer detail, slower.
    double detail = 1.0;
};

class Fractal final : public LeafPrimitive {
public:
    /// Estimate steps one query may take.
    static constexpr int max_steps = 4096;
    /// The inside walk's samples across the bounding ball's chord, at most.
    static constexpr int inside_samples = 512;

    /// Throws std::invalid_argument for a detail or footprint that is not
    /// positive (detail) or is negative (footprint).
    explicit Fractal(FractalDescription description);

    [[nodiscard]] Box3 bounds() const override { return bounds_; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const override;
    [[nodiscard]] const std::string& name() const override { return description_.name; }

    [[nodiscard]] const FractalEstimate& estimate() const { return *description_.estimate; }
    /// The hit tolerance, a length in the fractal's space, at a point `distance` from the ray's origin.
    [[nodiscard]] double tolerance_at(double distance) const;

private:
    /// One query's walk along a ray: its steps, within max_steps.
    struct Walk;
    /// The first t in [t, t_end] where the estimate drops below ε, by steps
    /// of the estimate; nothing if there is none (or the budget ran out).
    [[nodiscard]] std::optional<double> march(Walk& walk, double t, double t_end) const;
    /// Where the ray, in the solid at t, leaves it before t_end; nothing if it does not.
    [[nodiscard]] std::optional<double> exit_after(Walk& walk, double t, double t_end) const;
    [[nodiscard]] Hit boundary(const Ray& ray, double t, BoundaryKind kind) const;

    FractalDescription description_;
    Box3 bounds_;
    double radius_;  // the bounding ball's
};

}  // namespace zeroset
