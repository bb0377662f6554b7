// Sphere tracing on rays whose direction is not of unit length — the rays a
// transformed primitive passes to its child (eq. 36). The step H/L must use a
// bound on |H′| = |x_d·∇f|, not on |∇f| alone, or it steps over the surface.
#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

TEST(SphereMethod, HitsTheUnitSphereAlongALongDirection) {
    const Expr f = sqrt(square(var_x()) + square(var_y()) + square(var_z())) - 1.0;
    const Tape tape(f, SlotLayout::OnePerValue);
    const Bounds bounds = Bounds::make_box({{-10, -10, -10}, {10, 10, 10}});
    for (const double length : {10.0, 1e-4, 1e4}) {
        const Ray ray{{-9.9, 0, 0}, {length, 0, 0}};
        const auto span = bounds.clip(ray, 0.0, INFINITY);
        ASSERT_TRUE(span.has_value());
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const HitResult hit =
            make_root_finder(Method::Sphere, tape, settings_for_scale(bounds.box.diagonal()))->first_hit(h, *span, counters);
        ASSERT_TRUE(hit.t.has_value()) << "|x_d| = " << length;
        EXPECT_NEAR(*hit.t * length, 8.9, 1e-12) << "|x_d| = " << length;
    }
}

}  // namespace
}  // namespace zeroset
