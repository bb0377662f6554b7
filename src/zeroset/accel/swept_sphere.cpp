// A swept-sphere segment as a leaf: its exact spans clipped to the query's
// [t_min, t_max], and the normal of the sphere a hit lies on.
#include "zeroset/accel/swept_sphere.hpp"

#include <cmath>

#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

SweptSphere::SweptSphere(std::string name, const SweptSegment& segment, MaterialId material)
    : name_(std::move(name)), segment_(segment), material_(material), bounds_(segment.bounds()) {}

Hit SweptSphere::boundary(const Ray& ray, double t, BoundaryKind kind) const {
    return {t, leaf_surface(*this, kind, material_, ray.at(t), bounds_.diagonal())};
}

SweepSpans SweptSphere::exact_spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    if (!(t_min <= t_max) || !bounds_.clip(ray, t_min, t_max)) return {};
    SweepSpans found = sweep_spans(segment_, ray);
    scratch.counters.point_evaluations += static_cast<std::uint64_t>(found.evaluations);
    return found;
}

std::optional<Hit> SweptSphere::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    const SweepSpans found = exact_spans(ray, t_min, t_max, scratch);
    for (int i = 0; i < found.count; ++i) {
        const SweepSpan& s = found.spans[i];
        if (s.t_exit < t_min) continue;
        if (s.t_enter > t_max) break;
        if (s.t_enter >= t_min) return boundary(ray, s.t_enter, BoundaryKind::Surface);
        return boundary(ray, t_min, BoundaryKind::Open);  // the ray starts inside
    }
    return std::nullopt;
}

void SweptSphere::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const SweepSpans found = exact_spans(ray, t_min, t_max, scratch);
    for (int i = 0; i < found.count; ++i) {
        const SweepSpan& s = found.spans[i];
        if (s.t_exit < t_min) continue;
        if (s.t_enter > t_max) break;
        const bool starts_inside = s.t_enter < t_min, ends_inside = s.t_exit > t_max;
        out.push_back({boundary(ray, starts_inside ? t_min : s.t_enter, starts_inside ? BoundaryKind::Open : BoundaryKind::Surface),
                       boundary(ray, ends_inside ? t_max : s.t_exit, ends_inside ? BoundaryKind::Open : BoundaryKind::Surface)});
    }
}

Vec3d SweptSphere::local_normal(const SurfaceRef& surface, TraceScratch&) const {
    const Vec3d out = surface.local_point - segment_.center(sphere_through(segment_, surface.local_point));
    const double n = length(out);
    return n > 0.0 && std::isfinite(n) ? out / n : Vec3d{};
}

}  // namespace zeroset
