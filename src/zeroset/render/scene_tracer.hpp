// SceneTracer: the nearest hit of a ray over all objects of a scene, and
// shadow-ray occlusion. PreparedScene compiles each object once (tape,
// bounds, tolerances); each render thread owns a SceneTracer with its own
// evaluators over those shared tapes, so tracing never allocates or locks.
#pragma once

#include <optional>
#include <vector>

#include <memory>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/scene/scene.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {

struct PreparedObject {
    const Object* object;
    Tape tape;                    // SlotLayout::OnePerValue, so it can be pruned
    Box3 box;                     // the bounds' enclosing box
    Method method;                // resolved: never Method::Auto
    RootFinderSettings settings;  // tolerances relative to the bounds' size
};

class PreparedScene {
public:
    /// `method` and `solver`, when given, replace every object's own.
    explicit PreparedScene(const Scene& scene, std::optional<Method> method = std::nullopt,
                           std::optional<PolynomialSolver> solver = std::nullopt);

    [[nodiscard]] const Scene& scene() const { return *scene_; }
    [[nodiscard]] const std::vector<PreparedObject>& objects() const { return objects_; }
    /// The scene's lights, or — when it has none — one white point light at the camera.
    [[nodiscard]] const std::vector<Light>& lights() const { return lights_; }

private:
    const Scene* scene_;
    std::vector<Light> lights_;
    std::vector<PreparedObject> objects_;
};

struct SurfaceHit {
    double t;
    int object;    // index into the scene's objects
    Vec3d point;
    Vec3d normal;  // unit, facing the ray's origin
};

class SceneTracer {
public:
    explicit SceneTracer(const PreparedScene& prepared);

    /// The nearest surface along the ray (unit direction) in (0, t_max].
    std::optional<SurfaceHit> closest_hit(const Ray& ray, double t_max, TraceCounters& counters);
    /// True when some surface lies on the ray in (0, t_max].
    bool occluded(const Ray& ray, double t_max, TraceCounters& counters);

    [[nodiscard]] const PreparedScene& prepared() const { return *prepared_; }

    /// Where f first evaluated to NaN, if it did, and on which object.
    [[nodiscard]] const std::optional<std::pair<int, Vec3d>>& first_nan() const { return first_nan_; }

private:
    struct PerObject {
        RayFunction h;
        std::unique_ptr<RootFinder> finder;
        Evaluator<Dual<double>> gradient;
        Evaluator<double> value;
    };

    std::optional<double> first_hit(int index, const Ray& ray, double t_max, TraceCounters& counters);
    Vec3d surface_normal(int index, const Vec3d& p);

    const PreparedScene* prepared_;
    std::vector<PerObject> objects_;
    std::optional<std::pair<int, Vec3d>> first_nan_;
};

}  // namespace zeroset
