// RayProbe: one ray through one object, asked of several intersection
// methods in turn — first hit and all hits, with the evaluations each query
// spent and what the method logged — so that `zeroset ray` can compare the
// survey's methods on the same ray (DESIGN.md, "isolate, then refine").
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "zeroset/accel/half_space.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/search_region.hpp"

namespace zeroset {

/// The survey's ray (§1, eq. 4), with the anchor as its eq. (9) writes it.
/// The direction is used as given — it is not quite unit length, and the
/// survey's t values are for it as it is.
inline constexpr Vec3d survey_origin{-4.905, -0.67, 0.364};
inline constexpr Vec3d survey_dir{0.981, 0.174, 0.0872};

struct MethodOutcome {
    Method method;    // as asked; may be Method::Auto
    Method resolved;  // what ran: never Method::Auto

    std::optional<double> first_hit;
    HitStatus status = HitStatus::NoHit;
    std::uint64_t evaluations = 0;  // TraceCounters::evaluations() of the first-hit query

    std::vector<double> hits;
    HitStatus all_hits_status = HitStatus::NoHit;
    std::uint64_t all_hits_evaluations = 0;  // … of the all-hits query

    std::string message;  // why the method failed, when it threw
    MethodLog first_hit_log;
    MethodLog all_hits_log;
};

struct RayProbe {
    Ray ray;
    std::optional<Span> span;  // the ray in the search region, from t = 0; none when it misses it
    std::vector<MethodOutcome> methods;
    bool misses_gate = false;  // the object has a gate (Object::gate) and the ray misses it: no span
    /// The object has no bounds (a plane, a half-space): the span is the ray
    /// in a box about where it meets the plane (ObjectProbe::probe).
    bool unbounded = false;
};

/// Runs every method of `methods` on the ray: a fresh RootFinder for each
/// query, so neither query's evaluations or log include the other's. A
/// method that throws (e.g. one not implemented yet) is reported as failed
/// with the exception's message. `focus`: RayFunction::set_focus (NaN: none);
/// nothing when the ray misses the object's gate (gate_focus), and then no
/// method runs.
RayProbe probe_ray(const Tape& tape, const SearchRegion& region, const Ray& ray, std::span<const Method> methods,
                   const RootFinderSettings& settings,
                   std::optional<double> focus = std::numeric_limits<double>::quiet_NaN());

/// A placed object of a scene made ready for probing rays given in the
/// scene's space: its tape, its search region, and root-finder settings for
/// its size (with Newton's start when one is asked for). An object without
/// bounds — a plane, which the renderer traces in closed form (HalfSpace) —
/// is probed in a box about where each ray meets it, from the ray's origin
/// on: the methods then run as they would on the plane cut to that box.
class ObjectProbe {
public:
    ObjectProbe(const PlacedObject& placed, std::optional<double> newton_from);
    [[nodiscard]] RayProbe probe(const Ray& scene_ray, std::span<const Method> methods) const;
    [[nodiscard]] const Tape& tape() const { return tape_; }

private:
    /// A plane's probe: the box about the ray's meeting with it, per ray.
    [[nodiscard]] RayProbe probe_plane(const Ray& ray, std::span<const Method> methods) const;

    PlacedObject placed_;
    Tape tape_;
    std::optional<HalfSpace> plane_;     // when the object has no bounds
    std::optional<SearchRegion> region_;  // when it has
    RootFinderSettings settings_;
};

/// "auto (sphere)" for auto, else the method's name.
std::string method_label(const MethodOutcome& outcome);

}  // namespace zeroset
