// The isolating methods (interval, LG) where floor, mod, tan or atan2 jump
// inside an expression: no bound holds H′ across the jump and the enclosure
// of H does not shrink with the segment, so at the finest width only a sign
// change at the segment's ends may count as a root (refine_bracket.hpp).
// A continuous f built with mod (domain repetition) has no false hits on the
// jump planes; a discontinuous f that jumps through 0 is hit at the jump.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

HitResult first_hit(Method method, const Expr& f, const Ray& ray, Span span) {
    const Tape tape(f);
    RayFunction h(tape);
    h.set_ray(ray);
    TraceCounters counters;
    return make_root_finder(method, tape, settings_for_scale(10.0))->first_hit(h, span, counters);
}

TEST(JumpRays, RepeatedSpheresHaveNoHitsOnTheJumpPlanes) {
    // Balls of radius 0.3 repeated every unit along x and z, centred at
    // x, z ∈ ℤ + ½: f is continuous across x ∈ ℤ, where mod jumps. Over a
    // segment straddling x = −2 the enclosure of mod(x, 1) is all of [0, 1),
    // so at (y, z) = (−0.1, 0.3) the ball's enclosure reaches below 0 however
    // thin the segment — but the balls are 0.25 away: no hit.
    const Expr balls = sd_sphere({mod(X, Expr(1.0)) - 0.5, Y, mod(Z, Expr(1.0)) - 0.5}, 0.3);
    const Ray across{{-2.005, 0.4, 0.3}, normalize(Vec3d{0.01, -1.0, 0.0})};
    for (const Method method : {Method::Interval, Method::Lg}) {
        const HitResult miss = first_hit(method, balls, across, {0.0, 1.0});
        EXPECT_FALSE(miss.t.has_value()) << method_name(method) << ": a hit at " << miss.t.value_or(NAN);
        // Blended with a slab, down onto the balls and the slab across the planes z ∈ ℤ.
        const Expr f = smooth_union(balls, sd_box(coordinates(), {3, 0.05, 3}), 0.15);
        const Ray down{{-0.5, 2.0, -2.5}, normalize(Vec3d{0.3, -1.0, 1.0})};
        const HitResult hit = first_hit(method, f, down, {0.0, 5.0});
        ASSERT_TRUE(hit.t.has_value()) << method_name(method);
        const Vec3d p = down.at(*hit.t);
        const Tape tape(f);
        Evaluator<double> eval(tape);
        EXPECT_NEAR(eval(p.x, p.y, p.z), 0.0, 1e-9) << method_name(method);
    }
}

TEST(JumpRays, AJumpThroughZeroIsAHit) {
    // f = 1.5 − ⌊x⌋: 1.5, 0.5, then −0.5 from x = 2 on.
    for (const Method method : {Method::Interval, Method::Lg}) {
        const HitResult stairs = first_hit(method, 1.5 - floor(X), {{0.3, 0, 0}, {1, 0, 0}}, {0.0, 4.0});
        ASSERT_TRUE(stairs.t.has_value()) << method_name(method);
        EXPECT_NEAR(0.3 + *stairs.t, 2.0, 1e-9) << method_name(method);
        const HitResult pole = first_hit(method, 1.0 / tan(X) + Y, {{0.3, 0, 0}, {1, 0, 0}}, {0.0, 2.0});
        ASSERT_TRUE(pole.t.has_value()) << method_name(method);  // cot x reaches 0 at π/2, no jump there
        EXPECT_NEAR(0.3 + *pole.t, std::acos(0.0), 1e-9) << method_name(method);
        // atan2(y, x) + 3 going down through the cut at x = −1: about π + 3 − y, then −π + 3 + |y| < 0.
        const HitResult cut = first_hit(method, atan2(Y, X) + 3.0, {{-1.0, 0.05, 0}, {0, -1, 0}}, {0.0, 0.1});
        ASSERT_TRUE(cut.t.has_value()) << method_name(method);
        EXPECT_NEAR(*cut.t, 0.05, 1e-9) << method_name(method);
    }
}

}  // namespace
}  // namespace zeroset
