// A sign change across a pole is not a root: H = −1/x − 0.5 jumps from +∞ to
// −∞ at x = 0 without passing through 0, and no method may report a surface
// there. Roots on the same ray must still be found.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

const Bounds box2 = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
constexpr std::array non_polynomial_methods{Method::Interval, Method::Lg,          Method::Sphere,
                                            Method::RegulaFalsi, Method::Bisection};

TEST(Poles, ASignChangeAcrossAPoleIsNoHit) {
    const Expr f = -(Expr(1.0) / var_x()) - 0.5;
    const Tape tape(f);
    const Ray ray{{-1, 0.1, 0.1}, {1, 0, 0}};  // the ray, through x = 0 at t = 1
    for (const Method m : non_polynomial_methods) {
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const auto finder = make_root_finder(m, tape, settings_for_scale(box2.box.diagonal()));
        const HitResult hit = finder->first_hit(h, *box2.clip(ray, 0.0, INFINITY), counters);
        EXPECT_FALSE(hit.t.has_value()) << method_name(m) << " reported the pole at t = " << hit.t.value_or(NAN);
        EXPECT_EQ(hit.status, HitStatus::NoHit) << method_name(m);
    }
}

TEST(Poles, RootsBesideAPoleAreFound) {
    // A unit sphere divided by 3 − x: the same surface, and a pole at x = 3.
    const Bounds box = Bounds::make_box({{-2, -2, -2}, {5, 2, 2}});
    const Expr f = (square(var_x()) + square(var_y()) + square(var_z()) - 1.0) / (3.0 - var_x());
    const Tape tape(f);
    const Ray ray{{-2, 0, 0}, {1, 0, 0}};
    for (const Method m : {Method::Interval, Method::Lg, Method::Sphere}) {
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        std::vector<double> hits;
        make_root_finder(m, tape, settings_for_scale(box.box.diagonal()))
            ->all_hits(h, *box.clip(ray, 0.0, INFINITY), hits, counters);
        ASSERT_EQ(hits.size(), 2u) << method_name(m);
        EXPECT_NEAR(hits[0], 1.0, 1e-9) << method_name(m);  // x = −1
        EXPECT_NEAR(hits[1], 3.0, 1e-9) << method_name(m);  // x = 1, and none at the pole x = 3
    }
}

// Past a pole the search goes on: H = 1/(1 − x) + (x − 1) jumps from +∞ to
// −∞ at x = 1 and comes back to 0 at x = 2, the first root on a ray from
// x = 0.1 (sphere tracing used to stop at the pole: the ray was "inside").
TEST(Poles, TheRootPastAPoleIsTheFirstHit) {
    const Expr f = Expr(1.0) / (1.0 - var_x()) + (var_x() - 1.0);
    const Tape tape(f);
    const Bounds box = Bounds::make_box({{0.1, -1, -1}, {3, 1, 1}});
    const Ray ray{{0.1, 0.1, 0.1}, {1, 0, 0}};
    for (const Method m : {Method::Interval, Method::Lg, Method::Sphere}) {
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const HitResult hit = make_root_finder(m, tape, settings_for_scale(box.box.diagonal()))
                                  ->first_hit(h, *box.clip(ray, 0.0, INFINITY), counters);
        ASSERT_TRUE(hit.t.has_value()) << method_name(m);
        EXPECT_NEAR(ray.at(*hit.t).x, 2.0, 1e-9) << method_name(m);
    }
}

}  // namespace
}  // namespace zeroset
