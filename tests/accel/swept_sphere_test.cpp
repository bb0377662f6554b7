// Swept spheres (van Wijk 1984, survey §3.4) against computations that share
// none of their code: straight tubes — capsules and round cones — against
// their implicit expressions traced by the interval method, and curved tubes
// against a dense scan of the curve's spheres, each hit by the quadratic
// formula, on ten thousand rays (grazing ones among them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "zeroset/accel/group.hpp"
#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/swept_sphere.hpp"
#include "zeroset/accel/trace_scratch.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/shapes.hpp"

namespace zeroset {
namespace {

constexpr double far_t = 1e9;

struct SuiteRay {
    Ray ray;
    bool grazing;  // aimed along a tangent plane, where a root is ill-conditioned
};

/// A ray aimed at a random point near the origin from distance 6, and every
/// fourth one a ray grazing the solid where the previous one hit it (at
/// offsets from 0 to 10⁻³ off the tangent plane).
template <class HitOf, class NormalAt>
std::vector<SuiteRay> ray_suite(int count, unsigned seed, HitOf&& hit_of, NormalAt&& normal_at) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<SuiteRay> rays;
    while (static_cast<int>(rays.size()) < count) {
        const Vec3d target{1.3 * u(random), 1.3 * u(random), 1.3 * u(random)};
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{target - 6.0 * dir, dir};
        rays.push_back({ray, false});
        if (rays.size() % 4 != 0) continue;
        const std::optional<double> t = hit_of(ray);
        if (!t) continue;
        const Vec3d p = ray.at(*t), n = normal_at(p);
        Vec3d tangent = cross(n, Vec3d{u(random), u(random), u(random)});
        if (!(length(tangent) > 1e-3)) continue;
        tangent = normalize(tangent);
        const double offset = std::array{0.0, 1e-3, -1e-3, 1e-7, -1e-7}[rays.size() / 4 % 5];
        rays.push_back({{p + offset * n - 6.0 * tangent, tangent}, true});
    }
    return rays;
}

/// The implicit function of a straight round cone: with the segment a + s·e
/// and radius r0 + s·Δr, h(s) = |p − a − s·e|² − r(s)² is quadratic in s and
/// least at s* = −β/2α clamped to [0, 1] (α = |e|² − Δr² > 0), and h(s*) ≤ 0
/// exactly where p is in one of the spheres.
Expr round_cone_expression(const Vec3d& a, const Vec3d& b, double r0, double r1) {
    const ExprPoint p = coordinates();
    const Vec3d e = b - a;
    const double dr = r1 - r0, alpha = dot(e, e) - dr * dr;
    const Expr px = p.x - Expr(a.x), py = p.y - Expr(a.y), pz = p.z - Expr(a.z);
    const Expr beta = Expr(-2.0 * e.x) * px + Expr(-2.0 * e.y) * py + Expr(-2.0 * e.z) * pz - Expr(2.0 * r0 * dr);
    const Expr gamma = px * px + py * py + pz * pz - Expr(r0 * r0);
    const Expr s = max(Expr(0.0), min(Expr(1.0), -beta / Expr(2.0 * alpha)));
    return Expr(alpha) * s * s + beta * s + gamma;
}

struct Tally {
    int rays = 0, hits = 0, misses = 0, false_hits = 0, grazes = 0;
    double max_dt = 0.0;          // over the rays aimed at random
    double max_grazing_dt = 0.0;  // over the grazing ones

    void agree(const SuiteRay& r, double dt) {
        ++hits;
        double& largest = r.grazing ? max_grazing_dt : max_dt;
        largest = std::max(largest, dt);
    }
};

void expect_sound(const Tally& c, const char* what, int least_hits) {
    std::cout << what << ": " << c.rays << " rays, " << c.hits << " hit by both, max |dt| " << c.max_dt
              << " (grazing rays " << c.max_grazing_dt << "), " << c.grazes << " grazes, " << c.misses << " misses, "
              << c.false_hits << " false hits\n";
    EXPECT_EQ(c.misses, 0) << what;
    EXPECT_EQ(c.false_hits, 0) << what;
    EXPECT_LT(c.max_dt, 1e-8) << what;
    EXPECT_GT(c.hits, least_hits) << what;
}

/// The segment as a sweep primitive and as an expression traced by the
/// interval method: first hits agree on the ray suite, up to grazes (where
/// f at the point that one found and the other did not is within rounding).
void compare_with_expression(const SweptSegment& segment, const Expr& f, const char* what) {
    const SweptSphere sweep("sweep", segment, no_material);
    LeafDescription d;
    d.name = "expression";
    d.surface = f;
    Box3 box = sweep.bounds();
    box.lo -= Vec3d{0.1, 0.1, 0.1};
    box.hi += Vec3d{0.1, 0.1, 0.1};
    d.bounds = Bounds::make_box(box);
    d.method = Method::Interval;
    d.partition = Partition::None;
    const ImplicitLeaf reference(0, d);
    Evaluator<double> value(reference.tape());
    Evaluator<Dual<double>> gradient(reference.tape());
    const auto f_at = [&](const Vec3d& p) { return value(p.x, p.y, p.z); };
    TraceScratch scratch(1);
    const auto rays = ray_suite(
        10000, 7,
        [&](const Ray& ray) -> std::optional<double> {
            const auto h = reference.first_hit(ray, 0.0, far_t, scratch);
            return h ? std::optional(h->t) : std::nullopt;
        },
        [&](const Vec3d& p) { return normalize(evaluate_gradient(gradient, p).g); });
    Tally c;
    for (const SuiteRay& r : rays) {
        const Ray& ray = r.ray;
        ++c.rays;
        const auto mine = sweep.first_hit(ray, 0.0, far_t, scratch);
        const auto theirs = reference.first_hit(ray, 0.0, far_t, scratch);
        if (mine && theirs) {
            const double dt = std::abs(mine->t - theirs->t);
            if (dt > 1e-6) {
                const double early = std::min(mine->t, theirs->t);
                EXPECT_LT(std::abs(f_at(ray.at(early))), 1e-7) << what << ": t " << mine->t << " vs " << theirs->t;
                ++c.grazes;
            } else {
                c.agree(r, dt);
                // The normal is the expression's gradient, normalised.
                const Vec3d n = sweep.local_normal(mine->surface, scratch);
                const Vec3d g = evaluate_gradient(gradient, mine->surface.local_point).g;
                if (length(g) > 1e-3) {
                    EXPECT_LT(length(n - normalize(g)), 1e-6) << what;
                }
            }
        } else if (theirs) {
            (std::abs(f_at(ray.at(theirs->t))) > 1e-9 ? c.misses : c.grazes) += 1;
        } else if (mine) {
            (std::abs(f_at(ray.at(mine->t))) > 1e-9 ? c.false_hits : c.grazes) += 1;
        }
    }
    expect_sound(c, what, 2000);
}

TEST(SweptSphere, ACapsuleIsTheSphereSweptAlongALine) {
    const Vec3d a{-0.8, -0.3, 0.2}, b{0.9, 0.4, -0.3};
    compare_with_expression(SweptSegment(1, {a, b}, 0.35, 0.35), sd_capsule(coordinates(), a, b, 0.35), "capsule");
}

TEST(SweptSphere, ARoundConeIsASphereOfLinearRadiusSweptAlongALine) {
    const Vec3d a{-0.8, -0.3, 0.2}, b{0.9, 0.4, -0.3};
    compare_with_expression(SweptSegment(1, {a, b}, 0.55, 0.15), round_cone_expression(a, b, 0.55, 0.15), "round cone");
}

TEST(SweptSphere, ACubicThatRunsStraightIsTheSameRoundCone) {
    // Control points evenly spaced on the line: c(s) = a + s·(b − a), as a
    // cubic, so the degree-10 polynomial path meets the round cone exactly.
    const Vec3d a{-0.8, -0.3, 0.2}, b{0.9, 0.4, -0.3};
    const SweptSegment cubic(3, {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b}, 0.2, 0.5);
    compare_with_expression(cubic, round_cone_expression(a, b, 0.2, 0.5), "straight cubic");
    // Evenly spaced at ±1/3: its power basis's leading terms are rounding
    // noise (they are dropped), and rays at right angles to it have B ≈ 0.
    const SweptSegment thirds(3, {Vec3d{-1, 0, 0}, {-1.0 / 3, 0, 0}, {1.0 / 3, 0, 0}, {1, 0, 0}}, 0.3, 0.3);
    compare_with_expression(thirds, sd_capsule(coordinates(), {-1, 0, 0}, {1, 0, 0}, 0.3), "straight cubic at thirds");
}

TEST(SweptSphere, RaysAtRightAnglesAndPointPiecesAreExact) {
    // Perpendicular to a capsule's axis, the ray's nearest point is the
    // piece's middle: B ≈ 0 at the stretches' ends, where D is clamped.
    const SweptSphere capsule("c", SweptSegment(1, {Vec3d{-1, 0, 0}, {1, 0, 0}}, 0.3, 0.3), no_material);
    // A piece whose ends coincide is its spheres about one point: the largest.
    const SweptSphere point("p", SweptSegment(1, {Vec3d{0.2, 0, 0}, {0.2, 0, 0}}, 0.1, 0.5), no_material);
    TraceScratch scratch(1);
    std::mt19937 random(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const double angle = 3.14159 * u(random), x = 0.9 * u(random), h = 0.35 * u(random);
        const Vec3d d{0.0, -std::cos(angle), -std::sin(angle)};
        const Vec3d o = Vec3d{x, 0, 0} + Vec3d{0, -d.z, d.y} * h - 4.0 * d;  // passes h off the axis
        const auto hit = capsule.first_hit({o, d}, 0.0, far_t, scratch);
        if (std::abs(h) < 0.3) {
            ASSERT_TRUE(hit) << i;
            EXPECT_NEAR(hit->t, 4.0 - std::sqrt(0.09 - h * h), 1e-12) << i;
        } else {
            EXPECT_FALSE(hit) << i;
        }
        const Vec3d q = Vec3d{0.2, 0, 0} + Vec3d{0, -d.z, d.y} * h - 4.0 * d;
        const auto on_point = point.first_hit({q, d}, 0.0, far_t, scratch);
        ASSERT_TRUE(on_point) << i;
        EXPECT_NEAR(on_point->t, 4.0 - std::sqrt(0.25 - h * h), 1e-12) << i;
    }
}

/// The least of g over s ∈ [0, 1]: a scan of n + 1 values, then
/// golden-section search about the least of them.
template <class G>
double least_over_curve(G&& g, int n = 4000) {
    double best = g(0.0);
    int best_k = 0;
    for (int k = 1; k <= n; ++k)
        if (const double v = g(k / double(n)); v < best) best = v, best_k = k;
    double lo = std::max(0.0, (best_k - 1) / double(n)), hi = std::min(1.0, (best_k + 1) / double(n));
    for (int i = 0; i < 100; ++i) {
        const double m1 = lo + (hi - lo) * 0.381966, m2 = lo + (hi - lo) * 0.618034;
        if (g(m1) < g(m2)) hi = m2;
        else lo = m1;
    }
    return std::min(best, g(0.5 * (lo + hi)));
}

/// The first entry and the distance to the solid by scanning the curve's
/// spheres — the quadratic formula on each, and de Casteljau's points,
/// nothing of the code under test.
struct ScanOracle {
    const SweptSegment& segment;
    int samples = 4000;  // the scan's steps along the curve: fine enough that a step of c(s) is below the radius

    [[nodiscard]] Vec3d bezier(double s) const {
        std::array<Vec3d, 4> p = segment.control();
        for (int level = segment.degree(); level > 0; --level)
            for (int i = 0; i < level; ++i) p[i] = (1.0 - s) * p[i] + s * p[i + 1];
        return p[0];
    }
    [[nodiscard]] double radius(double s) const {
        return segment.radius_from() + (segment.radius_to() - segment.radius_from()) * s;
    }
    /// Where the ray enters sphere s, or far_t if it misses it.
    [[nodiscard]] double t_in(const Ray& ray, double s) const {
        const Vec3d w = ray.origin - bezier(s);
        const double a = dot(ray.dir, ray.dir), b = dot(ray.dir, w), c = dot(w, w) - radius(s) * radius(s);
        const double d = b * b - a * c;
        return d < 0.0 ? far_t : (-b - std::sqrt(d)) / a;
    }
    [[nodiscard]] std::optional<double> first(const Ray& ray) const {
        const double t = least_over_curve([&](double s) { return t_in(ray, s); }, samples);
        return t < far_t ? std::optional(t) : std::nullopt;
    }
    /// min over s of |p − c(s)| − r(s): the distance outside, negative inside.
    [[nodiscard]] double distance(const Vec3d& p) const {
        return least_over_curve([&](double s) { return length(p - bezier(s)) - radius(s); }, samples);
    }
};

TEST(SweptSphere, CurvedTubesMeetTheirFirstSphere) {
    const std::array<SweptSegment, 4> segments{
        // An S bend, a hook that turns back on itself, a quadratic arch, and
        // a U in the plane z = 0 (rays along it meet it where B′ = C′ = 0).
        SweptSegment(3, {Vec3d{-1.2, -0.6, 0}, {-0.2, 1.4, 0.3}, {0.2, -1.4, -0.3}, {1.2, 0.6, 0}}, 0.25, 0.25),
        SweptSegment(3, {Vec3d{-1, -0.8, 0.2}, {1.6, -0.6, 0.4}, {1.6, 0.9, -0.4}, {-1, 0.8, 0}}, 0.1, 0.45),
        SweptSegment(2, {Vec3d{-1.1, -0.7, 0}, {0, 1.6, 0.5}, {1.1, -0.7, 0}}, 0.3, 0.12),
        SweptSegment(3, {Vec3d{-1, -1, 0}, {-1, 1.5, 0}, {1, 1.5, 0}, {1, -1, 0}}, 0.3, 0.3),
    };
    constexpr std::array<const char*, 4> names{"S bend", "hook", "arch", "U"};
    for (std::size_t which = 0; which < segments.size(); ++which) {
        const SweptSegment& segment = segments[which];
        const SweptSphere sweep("sweep", segment, no_material);
        const ScanOracle oracle{segment};
        TraceScratch scratch(1);
        const auto rays = ray_suite(
            2500, 11 + static_cast<unsigned>(which), [&](const Ray& ray) { return oracle.first(ray); },
            [&](const Vec3d& p) { return normalize(p - segment.center(sphere_through(segment, p))); });
        Tally c;
        for (const SuiteRay& r : rays) {
            const Ray& ray = r.ray;
            ++c.rays;
            const auto mine = sweep.first_hit(ray, 0.0, far_t, scratch);
            const auto theirs = oracle.first(ray);
            if (mine && theirs) {
                // The scan's t is an upper bound of the true entry; a graze
                // the scan stepped over is a t far earlier on a point of the
                // surface.
                const double dt = std::abs(mine->t - *theirs);
                if (dt > 1e-6) {
                    EXPECT_LT(mine->t, *theirs);
                    EXPECT_LT(std::abs(oracle.distance(ray.at(mine->t))), 1e-7);
                    ++c.grazes;
                } else {
                    c.agree(r, dt);
                    // On the surface, with the normal of the sphere through it.
                    const Vec3d p = mine->surface.local_point;
                    EXPECT_NEAR(oracle.distance(p), 0.0, 1e-7);
                    const Vec3d n = sweep.local_normal(mine->surface, scratch);
                    EXPECT_NEAR(length(n), 1.0, 1e-12);
                    EXPECT_GT(oracle.distance(p + 1e-4 * n), 0.9e-4);
                }
            } else if (theirs) {
                // A miss unless the ray only touches: it must not reach 10⁻⁹ deep.
                double depth = 0.0;
                for (int k = 0; k <= 100; ++k) depth = std::min(depth, oracle.distance(ray.at(*theirs + k * 1e-4)));
                (depth < -1e-9 ? c.misses : c.grazes) += 1;
            } else if (mine) {
                (std::abs(oracle.distance(ray.at(mine->t))) > 1e-9 ? c.false_hits : c.grazes) += 1;
            }
        }
        expect_sound(c, names[which], 300);
    }
}

TEST(SweptSphere, AThinTubeIsMetWhereItsSpheresAre) {
    // Radius 10⁻³ on a curve 3 long: P is about 10⁻⁷ of its coefficients
    // inside a stretch, so its roots are found by the turns of φ. Rays aimed
    // across the tube at random points of the curve.
    const SweptSegment thin(3, {Vec3d{-1.2, -0.6, 0}, {-0.2, 1.4, 0.3}, {0.2, -1.4, -0.3}, {1.2, 0.6, 0}}, 1e-3, 1e-3);
    const SweptSphere sweep("thin", thin, no_material);
    const ScanOracle oracle{thin, 100000};
    TraceScratch scratch(1);
    std::mt19937 random(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3d target = thin.center(0.5 + 0.5 * u(random)) + Vec3d{u(random), u(random), u(random)} * 1.5e-3;
        const Vec3d dir = normalize(Vec3d{u(random), u(random), u(random)});
        const Ray ray{target - 3.0 * dir, dir};
        const auto mine = sweep.first_hit(ray, 0.0, far_t, scratch);
        const auto theirs = oracle.first(ray);
        ASSERT_EQ(mine.has_value(), theirs.has_value()) << i;
        if (!mine) continue;
        ++hits;
        EXPECT_NEAR(mine->t, *theirs, 1e-7) << i;  // a hundredth of the radius
    }
    EXPECT_GT(hits, 40);
}

TEST(SweptSphere, SpansRunFromTheFirstEntryToTheLastExit) {
    // A U-turn: a ray across both arms is inside twice; one along the
    // bend's inside is inside once, from the first sphere to the last.
    const SweptSegment u(3, {Vec3d{-1, -1, 0}, {-1, 1.5, 0}, {1, 1.5, 0}, {1, -1, 0}}, 0.2, 0.2);
    const SweptSphere sweep("u", u, no_material);
    TraceScratch scratch(1);
    SpanList spans;
    sweep.spans({{-3, -0.5, 0}, {1, 0, 0}}, 0.0, far_t, scratch, spans);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].enter.t, 2.0 - 0.2, 0.05);  // the arms run nearly along y at x = ±1
    EXPECT_LT(spans[0].exit.t, spans[1].enter.t);
    EXPECT_NEAR(spans[0].enter.t + spans[1].exit.t, 6.0, 1e-12);  // symmetric about x = 0
    EXPECT_NEAR(spans[0].exit.t + spans[1].enter.t, 6.0, 1e-12);
    // From inside: the span starts open at t_min.
    spans.clear();
    sweep.spans({{-1, -1, 0}, {0, 1, 0}}, 0.0, far_t, scratch, spans);
    ASSERT_FALSE(spans.empty());
    EXPECT_EQ(spans[0].enter.surface.kind, BoundaryKind::Open);
    EXPECT_EQ(spans[0].enter.t, 0.0);
    EXPECT_EQ(sweep.first_hit({{-1, -1, 0}, {0, 1, 0}}, 0.0, far_t, scratch)->surface.kind, BoundaryKind::Open);
    // Clipped by the query: nothing past t_max, an open exit inside it.
    spans.clear();
    sweep.spans({{-3, -0.5, 0}, {1, 0, 0}}, 0.0, 2.0, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].exit.t, 2.0);
    EXPECT_EQ(spans[0].exit.surface.kind, BoundaryKind::Open);
    EXPECT_FALSE(sweep.first_hit({{-3, -0.5, 0}, {1, 0, 0}}, 0.0, 1.5, scratch));
}

TEST(SweptSphere, SegmentsJoinedInAGroupAreOneTube) {
    // Two segments sharing an end: a ray through the joint sees one span.
    const Vec3d a{-1, 0, 0}, joint{0, 0.3, 0}, b{1, 0, 0};
    std::vector<std::shared_ptr<const Primitive>> parts{
        std::make_shared<const SweptSphere>("tube", SweptSegment(1, {a, joint}, 0.3, 0.3), no_material),
        std::make_shared<const SweptSphere>("tube", SweptSegment(1, {joint, b}, 0.3, 0.3), no_material)};
    const Group tube(std::move(parts), 1);
    TraceScratch scratch(1);
    SpanList spans;
    const Ray along{{-3, 0.1, 0}, {1, 0, 0}};
    tube.spans(along, 0.0, far_t, scratch, spans);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_LT(spans[0].enter.t, 2.0);
    EXPECT_GT(spans[0].exit.t, 4.0);
    const auto down = tube.first_hit({{0, 3, 0}, {0, -1, 0}}, 0.0, far_t, scratch);
    ASSERT_TRUE(down);
    EXPECT_NEAR(down->t, 3.0 - 0.3 - 0.3, 1e-12);  // the joint's sphere, at its top
}

TEST(SweptSphere, BadSegmentsAreRefused) {
    const std::array<Vec3d, 4> p{Vec3d{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    EXPECT_THROW(SweptSegment(0, p, 1, 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(4, p, 1, 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(3, p, -1, 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(3, p, 0, 0), std::invalid_argument);
    EXPECT_THROW(SweptSegment(3, p, std::nan(""), 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(1, {Vec3d{0, 0, 0}, {1e31, 0, 0}}, 1, 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(1, {Vec3d{0, 0, 0}, {1, 0, 0}}, 1e31, 1), std::invalid_argument);
    EXPECT_THROW(SweptSegment(2, {Vec3d{0, 0, 0}, {INFINITY, 0, 0}, {1, 1, 1}}, 1, 1), std::invalid_argument);
    // A point with a radius from 0: a cone's tip is allowed.
    EXPECT_NO_THROW(SweptSegment(1, p, 0, 1));
}

}  // namespace
}  // namespace zeroset
