// Sphere tracing on rays whose direction is not of unit length — the rays a
// transformed primitive passes to its child (eq. 36). The step H/L must use a
// bound on |H′| = |x_d·∇f|, not on |∇f| alone, or it steps over the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

TEST(SphereMethod, HitsTheUnitSphereAlongALongDirection) {
    const Expr f = sqrt(square(var_x()) + square(var_y()) + square(var_z())) - 1.0;
    const Tape tape(f);
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

// A caller may claim the ray is outside at t0 and be wrong — a later octree
// cell after a pole, where H changed sign without a root: the march stops
// there at once, and the start is the hit, as first_hit has it (not a miss
// of the whole span). Through the ball's centre, where H < 0, and from
// inside 1 − 2/x past its pole at 0, where H < 0 too.
TEST(SphereMethod, AStartWronglyClaimedOutsideIsTheHit) {
    const Expr ball = sqrt(square(var_x()) + square(var_y()) + square(var_z())) - 1.0;
    const Expr past_pole = 1.0 - 2.0 / var_x();
    for (const Expr& f : {ball, past_pole}) {
        const Tape tape(f);
        const auto method = make_root_finder(Method::Sphere, tape, settings_for_scale(10.0));
        const Ray ray{{0.5, 0.1, 0.2}, {1, 0, 0}};
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        ASSERT_LT(h.value(0.0, counters), 0.0);
        const HitResult claimed = method->first_hit_from_outside(h, {0.0, 4.0}, counters);
        const HitResult checked = method->first_hit(h, {0.0, 4.0}, counters);
        EXPECT_EQ(claimed.status, HitStatus::Ok);
        EXPECT_EQ(claimed.t, std::optional<double>(0.0));
        EXPECT_EQ(checked.t, claimed.t);
    }
}

TEST(SphereMethod, AStepThatLandsOnTheRootByAnExactBoundStillHits) {
    // Planes: H is linear and its Lipschitz bound exact (|n·x_d|), so a step
    // H/L lands on the root — or a few ulps past it by the rounding of H,
    // where the march must still report the crossing it stepped onto.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3d n = normalize(Vec3d{u(rng), u(rng), u(rng)});
        const double c = 0.5 * u(rng);
        const Tape tape(n.x * var_x() + n.y * var_y() + n.z * var_z() - c);
        const Bounds bounds = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
        const Vec3d from = 3.0 * normalize(Vec3d{u(rng), u(rng), u(rng)});
        const Ray ray{from, normalize(Vec3d{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)} - from)};
        const auto span = bounds.clip(ray, 0.0, INFINITY);
        if (!span) continue;
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const double h0 = h.value(span->t0, counters), h1 = h.value(span->t1, counters);
        if (!(h0 > 0.0 && h1 < 0.0)) continue;  // entering the half-space within the box
        const double root = span->t0 + (span->t1 - span->t0) * h0 / (h0 - h1);
        const HitResult hit = make_root_finder(Method::Sphere, tape, settings_for_scale(bounds.box.diagonal()))
                                  ->first_hit(h, *span, counters);
        ASSERT_TRUE(hit.t.has_value()) << "ray " << i;
        EXPECT_NEAR(*hit.t, root, 1e-9) << "ray " << i;
        ++hits;
    }
    EXPECT_GT(hits, 300);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

// Where a jump plane of mod meets a surface, an ε-segment has no finite
// Lipschitz bound; when only its far end is inside, the crossing must still
// be reported (it lies within the 2ε the method refines).
TEST(SphereMethod, FindsCrossingsOnSegmentsWithoutALipschitzBound) {
    const Expr x = var_x(), y = var_y(), z = var_z();
    const ExprPoint cell{mod(x, Expr(1.0)) - 0.5, y, mod(z, Expr(1.0)) - 0.5};
    const Expr f = smooth_union(sd_sphere(cell, 0.3), sd_box({x, y, z}, {3, 0.05, 3}), 0.15);
    const Tape tape(f);
    const Bounds bounds = Bounds::make_box({{-3.5, -0.5, -3.5}, {3.5, 0.5, 3.5}});
    const RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
    int compared = 0;
    for (int i = 0; i <= 200; ++i) {
        // Rays from (0, 3, −6) through points along the slab's front edge.
        const Vec3d target{-2.5 + 0.025 * i, 0.0, -3.0};
        const Ray ray{{0, 3, -6}, normalize(target - Vec3d{0, 3, -6})};
        const auto span = bounds.clip(ray, 0.0, INFINITY);
        if (!span) continue;
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const HitResult sphere = make_root_finder(Method::Sphere, tape, settings)->first_hit(h, *span, counters);
        const HitResult interval = make_root_finder(Method::Interval, tape, settings)->first_hit(h, *span, counters);
        ASSERT_EQ(sphere.t.has_value(), interval.t.has_value()) << i;
        if (!sphere.t) continue;
        ++compared;
        EXPECT_NEAR(*sphere.t, *interval.t, 2.0 * settings.sphere_epsilon) << i;
    }
    EXPECT_GT(compared, 150);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

// A ray that cuts a chord shorter than 2ε through one ball (found, since it
// is longer than ε) and then goes on through a second: after the first root
// the tracer resumes 2ε on — outside again — and must go on looking for an
// entry, not an exit, or it loses the second ball.
TEST(SphereMethod, AllHitsGoOnPastAShortChord) {
    const Expr x = var_x(), y = var_y(), z = var_z();
    const Bounds bounds = Bounds::make_box({{-1.5, -1.5, -1.5}, {4.5, 1.5, 1.5}});
    const RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
    const double eps = settings.sphere_epsilon;
    // Chord 2·sqrt(1 − d²) = 1.5ε.
    const double d = std::sqrt(1.0 - square(0.75 * eps));
    const Expr f = min(square(x) + square(y) + square(z) - 1.0, square(x - 3.0) + square(y - d) + square(z) - 1.0);
    const Tape tape(f);
    const Ray ray{{-1.4, d, 0}, {1, 0, 0}};
    RayFunction h(tape);
    h.set_ray(ray);
    TraceCounters counters;
    std::vector<double> hits;
    make_root_finder(Method::Sphere, tape, settings)->all_hits(h, *bounds.clip(ray, 0.0, INFINITY), hits, counters);
    std::vector<double> x_hits;
    for (const double t : hits) x_hits.push_back(ray.at(t).x);
    ASSERT_GE(x_hits.size(), 2u);
    EXPECT_NEAR(x_hits[x_hits.size() - 2], 2.0, 1e-9);  // the second ball, entered …
    EXPECT_NEAR(x_hits.back(), 4.0, 1e-9);               // … and left
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

/// A random sheet 0.05ε … 0.95ε thick across the unit box, and a ray from
/// outside towards the box's middle.
struct SheetCase {
    Expr plane;         // n·p for a random unit n
    double offset;      // the sheet is at n·p = offset
    double half_width;  // its half thickness
    Ray ray;
};

SheetCase random_sheet(std::mt19937_64& rng, double eps) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec3d n = normalize(Vec3d{u(rng), u(rng), u(rng)});
    SheetCase c{n.x * var_x() + n.y * var_y() + n.z * var_z(), 0.0, 0.0, {}};
    c.half_width = (0.05 + 0.45 * (u(rng) + 1.0)) * eps;
    c.offset = 0.3 * u(rng);
    const Vec3d from = 3.0 * normalize(Vec3d{u(rng), u(rng), u(rng)});
    c.ray = Ray{from, normalize(Vec3d{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)} - from)};
    return c;
}

const Bounds unit_box = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});

// Sheets thinner than ε: a step may land inside one (then the bracket must
// end where f ≤ 0, not 2ε on, past the sheet), or step onto an ε-segment
// positive at both ends with the sheet inside (then interval isolation must
// find it). Either way sphere tracing finds the root the interval method
// finds, on every ray.
TEST(SphereMethod, FindsSheetsThinnerThanEpsilon) {
    std::mt19937_64 rng(5);
    const Bounds& bounds = unit_box;
    const RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
    int found = 0;
    for (int i = 0; i < 2000; ++i) {
        const SheetCase c = random_sheet(rng, settings.sphere_epsilon);
        const Tape tape(abs(c.plane - c.offset) - c.half_width);
        const Ray& ray = c.ray;
        const auto span = bounds.clip(ray, 0.0, INFINITY);
        if (!span) continue;
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const HitResult interval = make_root_finder(Method::Interval, tape, settings)->first_hit(h, *span, counters);
        const HitResult sphere = make_root_finder(Method::Sphere, tape, settings)->first_hit(h, *span, counters);
        ASSERT_EQ(sphere.status, interval.status) << "ray " << i;
        ASSERT_EQ(sphere.t.has_value(), interval.t.has_value()) << "ray " << i;
        if (!sphere.t) continue;
        ++found;
        EXPECT_NEAR(*sphere.t, *interval.t, 1e-9) << "ray " << i;
    }
    EXPECT_GT(found, 300);
}

// All hits through such sheets: both faces of each, as the interval method
// finds them, though they are closer than the 2ε the march resumes after.
TEST(SphereMethod, AllHitsKeepBothFacesOfSheetsThinnerThanEpsilon) {
    std::mt19937_64 rng(8);
    const Bounds& bounds = unit_box;
    const RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
    int pairs = 0;
    for (int i = 0; i < 500; ++i) {
        const SheetCase c = random_sheet(rng, settings.sphere_epsilon);
        const Tape tape(min(abs(c.plane - c.offset) - c.half_width, abs(c.plane + 0.5) - c.half_width));
        const Ray& ray = c.ray;
        const auto span = bounds.clip(ray, 0.0, INFINITY);
        if (!span) continue;
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        std::vector<double> interval, sphere;
        const HitStatus interval_status =
            make_root_finder(Method::Interval, tape, settings)->all_hits(h, *span, interval, counters);
        const HitStatus sphere_status =
            make_root_finder(Method::Sphere, tape, settings)->all_hits(h, *span, sphere, counters);
        ASSERT_EQ(sphere_status, interval_status) << "ray " << i;
        ASSERT_EQ(sphere.size(), interval.size()) << "ray " << i;
        for (std::size_t k = 0; k < sphere.size(); ++k) EXPECT_NEAR(sphere[k], interval[k], 1e-9) << "ray " << i;
        pairs += static_cast<int>(sphere.size()) / 2;
    }
    EXPECT_GT(pairs, 100);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

// A sheet thinner than ε just past the span's end (as past the face of an
// octree cell) is not the span's: the ε-segment the march isolates at t1
// reaches 2ε beyond it, and a root found there must not be reported.
TEST(SphereMethod, ARootJustPastTheSpanIsNotReported) {
    const Bounds bounds = Bounds::make_box({{-1, -1, -1}, {3, 1, 1}});
    const RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
    const double eps = settings.sphere_epsilon;
    int rays = 0;
    for (const double past : {0.2, 0.5, 0.9, 1.3, 1.7}) {
        const double t1 = 2.0, sheet = t1 + past * eps;
        // A wobble keeps the slope bound loose, so steps stop short of the sheet.
        const Tape tape((abs(var_x() - sheet) - 0.1 * eps) * (1.0 + 1e-3 * sin(1e7 * var_x())));
        const Ray ray{{0, 0.1, 0.1}, {1, 0, 0}};
        RayFunction h(tape);
        h.set_ray(ray);
        TraceCounters counters;
        const HitResult hit = make_root_finder(Method::Sphere, tape, settings)->first_hit(h, {0.0, t1}, counters);
        EXPECT_FALSE(hit.t.has_value()) << "sheet " << past << "ε past t1: hit at " << hit.t.value_or(NAN);
        ++rays;
    }
    EXPECT_EQ(rays, 5);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

/// A random sheet (as above) and a wall beyond it, closer than 2ε and 1 to
/// 1 000 steep: w > 0 before it. The wall comes plain, or written as
/// max(w, 0) + min(w, 0) — w itself, but with kinks on its surface, as a
/// distance's max(d, 0) has them, so no enclosure of its slope over a
/// bracket there has one sign.
struct WallCase {
    SheetCase sheet;
    Expr across;  // the distance past the sheet's middle, along the ray
    Expr wall;
};

WallCase random_wall(std::mt19937_64& rng, double eps, bool kinked) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    WallCase c{random_sheet(rng, eps), {}, {}};
    const double gap = c.sheet.half_width + (0.05 + 1.9 * u(rng)) * eps;
    const double steep = std::pow(10.0, 3.0 * u(rng));
    const Tape plane(c.sheet.plane);
    RayFunction along(plane);
    along.set_ray(c.sheet.ray);
    TraceCounters counters;
    const double side = along.value(1.0, counters) > along.value(0.0, counters) ? 1.0 : -1.0;
    c.across = side * (c.sheet.plane - c.sheet.offset);
    const Expr w = steep * (gap - c.across);
    c.wall = kinked ? max(w, Expr(0.0)) + min(w, Expr(0.0)) : w;
    return c;
}

/// Over 3 000 such cases, the rays (clipped to the unit box) on which the
/// sphere method's first root differs from the interval method's, and
/// those with a root: `surface(case)` gives f, `first_root(method, tape,
/// settings, h, span)` a method's first root.
template <class Surface, class FirstRoot>
std::pair<int, int> wrong_first_roots(bool kinked, Surface&& surface, FirstRoot&& first_root) {
    const RootFinderSettings settings = settings_for_scale(unit_box.box.diagonal());
    std::mt19937_64 rng(21);
    int wrong = 0, rooted = 0;
    for (int i = 0; i < 3000; ++i) {
        const WallCase c = random_wall(rng, settings.sphere_epsilon, kinked);
        const Tape tape(surface(c));
        const auto span = unit_box.clip(c.sheet.ray, 0.0, INFINITY);
        if (!span) continue;
        RayFunction h(tape);
        h.set_ray(c.sheet.ray);
        const std::optional<double> interval = first_root(Method::Interval, tape, settings, h, *span);
        const std::optional<double> sphere = first_root(Method::Sphere, tape, settings, h, *span);
        if (!interval && !sphere) continue;
        ++rooted;
        if (!interval || !sphere || std::abs(*sphere - *interval) > 1e-9) ++wrong;
    }
    return {wrong, rooted};
}

// The sheet in front of the wall, closer to it than 2ε: the march's last
// bracket, from the last point outside to the first inside the wall, holds
// the sheet's two roots before the wall's. Its first root is the hit, not
// whichever one Newton's refinement lands on; with the kinked wall, steps
// clear the bracket or the interval isolation settles it.
TEST(SphereMethod, ASheetInFrontOfAWallWithinTheLastBracketIsTheHit) {
    for (const bool kinked : {false, true}) {
        const auto [wrong, hits] = wrong_first_roots(
            kinked, [](const WallCase& c) { return min(abs(c.across) - c.sheet.half_width, c.wall); },
            [](Method m, const Tape& tape, const RootFinderSettings& settings, RayFunction& h, Span span) {
                TraceCounters counters;
                return make_root_finder(m, tape, settings)->first_hit(h, span, counters).t;
            });
        EXPECT_EQ(wrong, 0) << "of " << hits << (kinked ? " (kinked wall)" : " (plain wall)");
        EXPECT_GT(hits, 300);
    }
}

// The same inside the solid, where all hits march −f: a cavity thinner than
// ε just before the back wall the ray leaves by. The first exit is the
// cavity's near face.
TEST(SphereMethod, ACavityBeforeTheBackWallIsTheFirstExit) {
    for (const bool kinked : {false, true}) {
        const auto [wrong, exits] = wrong_first_roots(
            kinked, [](const WallCase& c) { return max(-c.wall, c.sheet.half_width - abs(c.across)); },
            [](Method m, const Tape& tape, const RootFinderSettings& settings, RayFunction& h, Span span) {
                TraceCounters counters;
                std::vector<double> roots;
                if (h.value(span.t0, counters) >= 0.0) return std::optional<double>{};  // not from inside
                make_root_finder(m, tape, settings)->all_hits(h, span, roots, counters);
                return roots.empty() ? std::optional<double>{} : std::optional<double>{roots.front()};
            });
        EXPECT_EQ(wrong, 0) << "of " << exits << (kinked ? " (kinked wall)" : " (plain wall)");
        EXPECT_GT(exits, 300);
    }
}

}  // namespace
}  // namespace zeroset
