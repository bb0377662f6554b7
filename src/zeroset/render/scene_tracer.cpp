// Nearest-hit search over objects, with normals (eqs. 33 and 34).
#include "zeroset/render/scene_tracer.hpp"

#include <cmath>

#include "zeroset/trace/choose_method.hpp"

namespace zeroset {

PreparedScene::PreparedScene(const Scene& scene, std::optional<Method> method, std::optional<PolynomialSolver> solver)
    : scene_(&scene), lights_(scene.lights) {
    if (lights_.empty()) lights_.push_back({Light::Kind::Point, scene.camera.from, {}, {1.0, 1.0, 1.0}, true});
    objects_.reserve(scene.objects.size());
    for (const Object& object : scene.objects) {
        Tape tape(object.surface, SlotLayout::OnePerValue);
        const Box3 box = object.bounds.enclosing_box();
        const Method resolved = resolve_method(method.value_or(object.method), tape);
        RootFinderSettings settings = settings_for_scale(box.diagonal());
        settings.polynomial_solver = solver.value_or(object.solver);
        objects_.push_back({&object, std::move(tape), box, resolved, settings});
    }
}

SceneTracer::SceneTracer(const PreparedScene& prepared) : prepared_(&prepared) {
    objects_.reserve(prepared.objects().size());
    for (const PreparedObject& o : prepared.objects())
        objects_.push_back({RayFunction(o.tape), make_root_finder(o.method, o.tape, o.settings),
                            Evaluator<Dual<double>>(o.tape), Evaluator<double>(o.tape)});
}

std::optional<double> SceneTracer::first_hit(int index, const Ray& ray, double t_max, TraceCounters& counters) {
    const PreparedObject& o = prepared_->objects()[static_cast<std::size_t>(index)];
    const auto span = o.object->bounds.clip(ray, 0.0, t_max);
    if (!span) return std::nullopt;
    PerObject& per = objects_[static_cast<std::size_t>(index)];
    const std::uint64_t nans_before = counters.nan_evaluations;
    per.h.set_ray(ray);
    const HitResult hit = per.finder->first_hit(per.h, *span, counters);
    if (counters.nan_evaluations != nans_before && !first_nan_) first_nan_ = {index, per.h.last_nan_point()};
    return hit.t;
}

std::optional<SurfaceHit> SceneTracer::closest_hit(const Ray& ray, double t_max, TraceCounters& counters) {
    std::optional<SurfaceHit> best;
    for (int i = 0; i < static_cast<int>(objects_.size()); ++i) {
        const double limit = best ? best->t : t_max;
        if (const auto t = first_hit(i, ray, limit, counters); t && (!best || *t < best->t))
            best = SurfaceHit{*t, i, ray.at(*t), {}};
    }
    if (best) {
        best->normal = surface_normal(best->object, best->point);
        if (best->normal == Vec3d{}) best->normal = -ray.dir;  // no usable gradient here
        if (dot(best->normal, ray.dir) > 0.0) best->normal = -best->normal;
    }
    return best;
}

bool SceneTracer::occluded(const Ray& ray, double t_max, TraceCounters& counters) {
    for (int i = 0; i < static_cast<int>(objects_.size()); ++i)
        if (first_hit(i, ray, t_max, counters)) return true;
    return false;
}

Vec3d SceneTracer::surface_normal(int index, const Vec3d& p) {
    const PreparedObject& o = prepared_->objects()[static_cast<std::size_t>(index)];
    PerObject& per = objects_[static_cast<std::size_t>(index)];
    Vec3d g;
    if (o.object->normals == NormalMode::Analytic) {
        g = evaluate_gradient(per.gradient, p).g;  // eq. 33
    } else {
        const double h = o.settings.sphere_epsilon;  // eq. 34: forward differences
        const double f0 = per.value(p.x, p.y, p.z);
        g = Vec3d{per.value(p.x + h, p.y, p.z) - f0, per.value(p.x, p.y + h, p.z) - f0,
                  per.value(p.x, p.y, p.z + h) - f0} / h;
    }
    const double len = length(g);
    if (!(len > 0.0) || !std::isfinite(len)) return {0.0, 0.0, 0.0};  // no usable gradient
    return g / len;
}

}  // namespace zeroset
