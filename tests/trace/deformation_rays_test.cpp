// Sphere tracing on deformed distance functions (survey §9 with §5.2): the
// twist, taper and bend make f∘D⁻¹ no distance any more, and the sphere
// tracer's step must come from the interval Lipschitz bound alone. On a few
// thousand random unit-direction rays through each object's bounds it must
// find the same first hit as the interval method (which never misses) to
// within 2ε: never a hit after a crossing the interval method proves, never
// one before it. Only grazes — the ray inside the solid for less than 4ε —
// may be passed; they are counted and must be rare.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "support/bounds_proof.hpp"
#include "zeroset/expr/deform.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

struct DeformedObject {
    std::string name;
    Expr f;
    Box3 bounds;  // holds the deformed surface
};

std::vector<DeformedObject> objects() {
    const ExprPoint p = coordinates();
    // A torus (R = 1, r = 0.3, around z) twisted about x, the axis through its ring:
    // a twist keeps |x| ≤ 1.3 and the distance √(y² + z²) ≤ √(1.3² + 0.3²) < 1.34.
    const Expr twisted_torus = twist(sd_torus(p, 1.0, 0.3), Twist({1, 0, 0}, 0.9));
    // A column along z tapered towards the top, its upper half bent towards x.
    const Expr column = sd_cylinder(p, 0.4, 1.5);
    const Expr bent_column = bend(taper(column, Taper({0, 0, 1}, -0.3)), Bend({0, 0, 1}, {1, 0, 0}, 0.45, 0.0, 1.5));
    // A twisted bar and a bent slab blended smoothly.
    const Expr bar = twist(sd_box(p, {0.25, 0.25, 1.2}), Twist({0, 0, 1}, 1.4));
    const Expr slab = bend(sd_round_box(p, {0.9, 0.15, 0.5}, 0.05), Bend({1, 0, 0}, {0, 1, 0}, -0.6));
    return {
        {"twisted torus", twisted_torus, {{-1.35, -1.36, -1.36}, {1.35, 1.36, 1.36}}},
        {"tapered bent column", bent_column, {{-0.7, -0.7, -1.55}, {1.0, 0.7, 1.6}}},
        {"twisted bar and bent slab", smooth_union(bar, slab, 0.2), {{-1.0, -0.6, -1.25}, {1.0, 0.6, 1.25}}},
    };
}

// The bounds hold each surface: f > 0 all over the bounds' six faces.
TEST(DeformationRays, BoundsHoldTheDeformedSurfaces) {
    for (const DeformedObject& object : objects())
        EXPECT_TRUE(test::unproven_faces(object.f, object.bounds, 7).empty()) << object.name;
}

TEST(DeformationRays, SphereTracingFindsTheIntervalMethodsFirstHit) {
    std::mt19937_64 rng(2024);
    const auto uniform = [&rng](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    for (const DeformedObject& object : objects()) {
        SCOPED_TRACE(object.name);
        const Tape tape(object.f);
        const Vec3d diagonal = object.bounds.hi - object.bounds.lo;
        const double scale = length(diagonal);
        const RootFinderSettings settings = settings_for_scale(scale);
        const double eps = settings.sphere_epsilon, slack = 1e-9 * scale;
        const auto sphere = make_root_finder(Method::Sphere, tape, settings);
        const auto interval = make_root_finder(Method::Interval, tape, settings);
        RayFunction h(tape);
        TraceCounters counters;
        int rays = 0, hits = 0, grazes = 0;
        for (int n = 0; n < 1200; ++n) {
            // From a sphere around the bounds towards a random point inside them.
            const Vec3d centre = object.bounds.center();
            const Vec3d from = centre + normalize(Vec3d{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}) * scale;
            const Box3& b = object.bounds;
            const Vec3d to{uniform(b.lo.x, b.hi.x), uniform(b.lo.y, b.hi.y), uniform(b.lo.z, b.hi.z)};
            const Ray ray{from, normalize(to - from)};
            const std::optional<Span> span = object.bounds.clip(ray, 0.0, 1e30);
            if (!span) continue;
            ++rays;
            h.set_ray(ray);
            const HitResult reference = interval->first_hit(h, *span, counters);
            const HitResult traced = sphere->first_hit(h, *span, counters);
            ASSERT_NE(reference.status, HitStatus::Failed);
            ASSERT_NE(traced.status, HitStatus::Failed);
            const std::string where = "ray from (" + std::to_string(from.x) + ", " + std::to_string(from.y) + ", " +
                                      std::to_string(from.z) + ") to (" + std::to_string(to.x) + ", " +
                                      std::to_string(to.y) + ", " + std::to_string(to.z) + ")";
            if (!reference.t) {
                // No root in the span: a sphere hit can only be a root a hair past t1 (its 2ε look-ahead).
                if (traced.t) { EXPECT_GE(*traced.t, span->t1 - 2 * eps - slack) << where; }
                continue;
            }
            ++hits;
            const double t = *reference.t;
            if (traced.t) { EXPECT_GE(*traced.t, t - 2 * eps - slack) << "a hit before the first root: " << where; }
            // A crossing: the ray stays inside for more than 4ε after the root.
            bool crossing = true;
            for (const double dt : {1.5 * eps, 2.5 * eps, 4 * eps})
                crossing = crossing && t + dt <= span->t1 && h.value(t + dt, counters) < 0.0;
            if (crossing) {
                ASSERT_TRUE(traced.t.has_value()) << "sphere tracing missed a crossing at t = " << t << ": " << where;
                EXPECT_LE(*traced.t, t + 2 * eps + slack) << "sphere tracing stepped over the first root: " << where;
            } else if (!traced.t || *traced.t > t + 2 * eps + slack) {
                ++grazes;
            }
        }
        std::printf("%s: %d rays, %d hits, %d grazes passed by sphere tracing\n", object.name.c_str(), rays, hits,
                    grazes);
        EXPECT_GT(rays, 1000);
        EXPECT_GT(hits, rays / 5);
        EXPECT_LE(grazes, rays / 100);
    }
}

}  // namespace
}  // namespace zeroset
