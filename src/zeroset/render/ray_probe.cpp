// Running the methods on one ray.
#include "zeroset/render/ray_probe.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "zeroset/trace/choose_method.hpp"

namespace zeroset {

namespace {

void run_method(MethodOutcome& o, const Tape& tape, const Ray& ray, Span span, double focus,
                const RootFinderSettings& settings) {
    RayFunction h(tape);
    h.set_ray(ray);
    h.set_focus(focus);
    RootFinderSettings s = settings;
    auto note_failure = [&o](HitStatus& status, const std::exception& e) {
        status = HitStatus::Failed;
        if (o.message.empty()) o.message = e.what();
    };

    TraceCounters first_counters;
    try {
        s.log = &o.first_hit_log;
        const HitResult hit = make_root_finder(o.resolved, tape, s)->first_hit(h, span, first_counters);
        o.first_hit = hit.t;
        o.status = hit.status;
    } catch (const std::exception& e) {
        note_failure(o.status, e);
    }
    o.evaluations = first_counters.evaluations();

    TraceCounters all_counters;
    try {
        s.log = &o.all_hits_log;
        o.all_hits_status = make_root_finder(o.resolved, tape, s)->all_hits(h, span, o.hits, all_counters);
    } catch (const std::exception& e) {
        note_failure(o.all_hits_status, e);
    }
    o.all_hits_evaluations = all_counters.evaluations();
}

}  // namespace

RayProbe probe_ray(const Tape& tape, const SearchRegion& region, const Ray& ray, std::span<const Method> methods,
                   const RootFinderSettings& settings, std::optional<double> focus) {
    RayProbe probe{ray, std::nullopt, {}, !focus};
    if (focus) probe.span = region.clip(ray, 0.0, std::numeric_limits<double>::infinity());
    for (const Method m : methods) {
        MethodOutcome& o = probe.methods.emplace_back();
        o.method = m;
        o.resolved = resolve_method(m, tape);
        if (probe.span) run_method(o, tape, ray, *probe.span, *focus, settings);
    }
    return probe;
}

std::string method_label(const MethodOutcome& outcome) {
    if (outcome.method == Method::Auto) return "auto (" + std::string(method_name(outcome.resolved)) + ")";
    return std::string(method_name(outcome.method));
}

ObjectProbe::ObjectProbe(const PlacedObject& placed, std::optional<double> newton_from)
    : placed_(placed), tape_(surface_of(placed.object())) {
    const Object& o = placed.object();
    if (o.bounds.kind == Bounds::Kind::None) {
        // As the renderer takes it (PreparedScene): a plane, or an error.
        if (o.gate) throw std::invalid_argument("a gate needs bounds (without, it is a half-space)");
        plane_.emplace(std::string(), o.surface, no_material);
    } else {
        region_.emplace(tape_, narrowed_to_clip(o.bounds, o.clip, o.open));  // as ImplicitLeaf
        settings_ = settings_for_scale(gated_scale(region_->scale(), o.gate));
    }
    settings_.newton_start = newton_from;
}

RayProbe ObjectProbe::probe(const Ray& scene_ray, std::span<const Method> methods) const {
    // The methods run as the renderer runs them (ImplicitLeaf::searched_span).
    const Ray ray = to_object_space(placed_, scene_ray);
    if (plane_) return probe_plane(ray, methods);
    const std::optional<Bounds>& gate = placed_.object().gate;
    const std::optional<double> focus = gate ? gate_focus(*gate, ray, 0.0) : std::numeric_limits<double>::quiet_NaN();
    return probe_ray(tape_, *region_, ray, methods, settings_, focus);
}

RayProbe ObjectProbe::probe_plane(const Ray& ray, std::span<const Method> methods) const {
    // f(o + t·d) = f(o) + t·(n·d): the ray meets the plane at t*. The box is
    // centred there (at the origin when t* is not ahead) and reaches back to
    // the origin, and at least to the plane: so a ray from inside starts in
    // it, and one that never meets the plane misses its shrunk slab.
    const Vec3d& n = plane_->normal();
    const double at_origin = dot(n, ray.origin) + plane_->offset();
    const double meets = -at_origin / dot(n, ray.dir);
    const bool ahead = meets > 0.0 && std::isfinite(meets);
    const Vec3d centre = ahead ? ray.at(meets) : ray.origin;
    const double half = std::max({length(centre - ray.origin), std::abs(at_origin) / length(n),
                                  1e-9 * (1.0 + max_abs(ray.origin))});
    const Vec3d reach{half, half, half};
    const SearchRegion region(tape_, Bounds::make_box({centre - reach, centre + reach}));
    RootFinderSettings settings = settings_for_scale(region.scale());
    settings.newton_start = settings_.newton_start;
    RayProbe probe = probe_ray(tape_, region, ray, methods, settings);
    probe.unbounded = true;
    return probe;
}

}  // namespace zeroset
