// The ray suite (tests/data/ray_suite.tsv, support/ray_suite.hpp): its shape,
// a few hundred of its MPFI references checked against dense double sampling
// (an independent check of the oracle), and the sphere tracer run over every
// ray. Sphere tracing guarantees today that it never steps over the first
// root: a hit lies within 2ε of the reference, and only a graze — a ray that
// is inside the surface for less than 2ε, or touches it — may be missed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "support/ray_suite.hpp"
#include "support/ray_suite_surfaces.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/trace/polynomial_method.hpp"
#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/sphere_tracer.hpp"

namespace zeroset::test {
namespace {

const std::vector<SuiteRay>& suite() {
    static const std::vector<SuiteRay> rays =
        load_ray_suite(std::filesystem::path(ZEROSET_SOURCE_DIR) / "tests" / "data" / "ray_suite.tsv");
    return rays;
}

/// Where a ray leaves the solid after its first root, as far as [t0, t1] shows: the next root, or t1.
double dip_end(const SuiteRay& r) { return r.t_next.value_or(r.span.t1); }

std::string describe(const SuiteRay& r) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s/%s o=(%.17g, %.17g, %.17g) d=(%.17g, %.17g, %.17g) span=[%.17g, %.17g] ref=%s %.17g",
                  r.surface.c_str(), r.ray_class.c_str(), r.ray.origin.x, r.ray.origin.y, r.ray.origin.z, r.ray.dir.x,
                  r.ray.dir.y, r.ray.dir.z, r.span.t0, r.span.t1, std::string(ref_kind_name(r.kind)).c_str(),
                  r.t_ref.value_or(NAN));
    return text;
}

TEST(RaySuite, IsLargeAndCoversEveryCase) {
    const auto& rays = suite();
    EXPECT_GE(rays.size(), 10000U);
    std::set<std::string> surfaces, classes;
    std::map<RefKind, int> kinds;
    for (const SuiteRay& r : rays) {
        const SuiteSurface& s = ray_suite_surface(r.surface);
        ASSERT_DOUBLE_EQ(r.scale, s.scale()) << describe(r);  // written as %.17g; the diagonal is hypot
        ASSERT_LT(r.span.t0, r.span.t1) << describe(r);
        ASSERT_NEAR(length(r.ray.dir), 1.0, 1e-15) << describe(r);
        if (r.t_ref) {
            ASSERT_GE(*r.t_ref, r.span.t0) << describe(r);
            ASSERT_LE(*r.t_ref, r.span.t1) << describe(r);
        }
        if (r.t_next) {
            ASSERT_TRUE(r.t_ref.has_value()) << describe(r);
            ASSERT_GT(*r.t_next, *r.t_ref) << describe(r);
        }
        surfaces.insert(r.surface);
        classes.insert(r.ray_class);
        ++kinds[r.kind];
    }
    EXPECT_EQ(surfaces.size(), ray_suite_surfaces().size());
    for (const char* c : {"random", "graze", "graze_approx", "near_miss", "shallow", "near_t0", "near_t1", "past_t1",
                          "thin", "singular"})
        EXPECT_TRUE(classes.contains(c)) << c;
    EXPECT_GE(kinds[RefKind::Simple], 5000);
    EXPECT_GE(kinds[RefKind::Tangent], 300);
    EXPECT_GE(kinds[RefKind::Multiple], 1);
    EXPECT_GE(kinds[RefKind::None], 3000);
}

/// f along a ray in plain doubles, one evaluator per surface.
class DoubleRayFunction {
public:
    double operator()(const SuiteRay& r, double t) {
        auto& slot = evaluators_[r.surface];
        if (!slot) {
            tapes_.push_back(std::make_unique<Tape>(ray_suite_surface(r.surface).f));
            slot = std::make_unique<Evaluator<double>>(*tapes_.back());
        }
        const Vec3d p = r.ray.at(t);
        return (*slot)(p.x, p.y, p.z);
    }

private:
    std::vector<std::unique_ptr<Tape>> tapes_;
    std::map<std::string, std::unique_ptr<Evaluator<double>>> evaluators_;
};

// Every 37th ray (about 300) is sampled at 20 000 points in plain doubles.
// A sample clearly below 0 proves a root at or before it, which the reference
// must have found; and a simple root whose dip is several samples wide must
// be where the samples first change sign — where, if it is steep enough for
// doubles to see its sign change sharply, bisecting the sign change in
// doubles lands within 1e-11 × scale of it.
TEST(RaySuite, ReferencesAgreeWithDenseSampling) {
    constexpr std::size_t every = 37;
    constexpr int samples = 20000;
    constexpr double clearly_negative = -1e-12;
    DoubleRayFunction h;
    int sampled = 0, bracketed = 0, refined = 0;
    const auto& rays = suite();
    for (std::size_t i = 0; i < rays.size(); i += every) {
        const SuiteRay& r = rays[i];
        const double spacing = (r.span.t1 - r.span.t0) / samples, slack = 1e-12 * r.scale;
        const auto at = [&](int j) { return j == samples ? r.span.t1 : r.span.t0 + j * spacing; };
        int first_nonpositive = -1, first_negative = -1;
        for (int j = 0; j <= samples && first_negative < 0; ++j) {
            const double value = h(r, at(j));
            if (value <= 0.0 && first_nonpositive < 0) first_nonpositive = j;
            if (value < clearly_negative) first_negative = j;
        }
        ++sampled;
        if (first_negative >= 0) {
            ASSERT_TRUE(r.t_ref.has_value())
                << "sampling finds f < 0 at t = " << at(first_negative) << ": " << describe(r);
            EXPECT_LE(*r.t_ref, at(first_negative) + slack) << describe(r);
        }
        const bool resolvable =
            r.kind == RefKind::Simple && dip_end(r) - *r.t_ref >= 3.0 * spacing && r.slope * spacing >= 1e-9;
        if (!resolvable) continue;
        ++bracketed;
        ASSERT_GE(first_nonpositive, 0) << describe(r);
        EXPECT_GE(*r.t_ref, at(first_nonpositive) - 2.0 * spacing) << describe(r);
        EXPECT_LE(*r.t_ref, at(first_nonpositive) + slack) << describe(r);
        if (first_nonpositive == 0 || r.slope < 0.01) continue;
        double lo = at(first_nonpositive - 1), hi = at(first_nonpositive);
        for (int k = 0; k < 100 && lo < hi; ++k) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (h(r, mid) > 0.0 ? lo : hi) = mid;
        }
        ++refined;
        EXPECT_NEAR(hi, *r.t_ref, 1e-11 * r.scale) << describe(r);
    }
    std::printf("dense sampling: %d rays sampled, %d simple roots bracketed, %d refined in doubles\n", sampled,
                bracketed, refined);
    EXPECT_GE(bracketed, 100);
    EXPECT_GE(refined, 80);
}

struct TracerTally {
    int hits = 0;
    int isolated = 0;     // settled by interval isolation in an ε-segment
    int tangent = 0;      // a hit before the reference where H is 0 to double precision
    int beyond_span = 0;  // a hit where the oracle proves no root in [t0, t1]
};

/// Rays reach a primitive through its transforms with directions of any
/// length (eq. 36): every method runs on the suite with x_d scaled by these.
/// A hit at t on the scaled ray is at t·s on the suite's own ray.
constexpr std::array direction_scales{1.0, 0.37, 1e-3, 1e3};

Ray scaled_ray(const SuiteRay& r, double s) { return {r.ray.origin, r.ray.dir * s}; }
Span scaled_span(const SuiteRay& r, double s) { return {r.span.t0 / s, r.span.t1 / s}; }

class RaySuiteScaled : public ::testing::TestWithParam<double> {};

// The sphere tracer (ε = 1e-6 × scale) on every ray: the first root lies in
// the crossing it reports, [hit, end] — within 2ε, a bracket it proved holds
// one root, or the root itself where an ε-segment was isolated by
// intervals. So it never misses a root, grazes and sheets thinner than ε
// included, and never steps past the first one. A crossing ending before the
// reference is allowed only as the interval method allows a hit there: where
// the enclosure of H over it still holds 0 (a ray grazing closer than
// rounding can resolve); and the crossing's start is
// never past the root by more than doubles can place it. Hits on rays whose root lies a
// hair past t1 (found by the 2ε look-ahead) are counted and printed.
TEST_P(RaySuiteScaled, SphereTracerNeverSkipsTheFirstHit) {
    const double s = GetParam();
    std::map<std::string, std::unique_ptr<Tape>> tapes;
    std::map<std::string, TracerTally> tallies;
    std::map<std::string, int> reported;
    const auto report = [&](const std::string& what, const SuiteRay& r, std::optional<double> hit) {
        if (++reported[what] <= 3)
            std::printf("sphere tracer, %s: %s hit=%.17g\n", what.c_str(), describe(r).c_str(), hit.value_or(NAN));
    };
    for (const SuiteRay& r : suite()) {
        auto& tape = tapes[r.surface];
        const double eps = 1e-6 * r.scale, slack = 1e-12 * r.scale, tangent_width = 1e-10 * r.scale;
        if (!tape) tape = std::make_unique<Tape>(ray_suite_surface(r.surface).f);
        const SphereTracer tracer(SphereTraceSettings{.epsilon = eps, .tangent_width = tangent_width});
        RayFunction h(*tape);
        h.set_ray(scaled_ray(r, s));
        TracerTally& tally = tallies[r.surface];
        TraceCounters counters;
        const Crossing crossed = tracer.first_hit(h, scaled_span(r, s), counters);
        std::optional<double> hit = crossed.t;
        const double end = s * crossed.end;
        if (hit) *hit *= s;
        if (hit) ++tally.hits;
        if (crossed.exact) ++tally.isolated;
        // A crossing where no root is known: H must be 0 to double precision in it.
        const auto expect_h_may_vanish = [&] {
            RayFunction unscaled(*tape);
            unscaled.set_ray(r.ray);
            const Interval there = unscaled.enclose(*hit, crossed.exact ? *hit + tangent_width : end, counters).v;
            EXPECT_TRUE(there.contains(0.0)) << "hit where H is not 0: " << describe(r) << " hit=" << *hit
                                             << " H in [" << there.lo << ", " << there.hi << "]";
        };
        if (!r.t_ref) {
            if (hit) {
                ++tally.beyond_span;
                const bool past_t1 = r.ray_class == "past_t1";
                report(past_t1 ? "hit with the root a hair past t1" : "hit where the oracle proves no root", r, hit);
                if (!past_t1) expect_h_may_vanish();
            }
            continue;
        }
        if (!hit) {
            ADD_FAILURE() << "missed the first root: " << describe(r);
            continue;
        }
        // As precise as doubles place the root: see expect_strict below.
        const double late = (r.kind == RefKind::Simple && r.slope >= 1e-6 ? 1e-9 : 1e-7) * r.scale;
        EXPECT_LE(*hit, *r.t_ref + late) << "stepped over the first root: " << describe(r) << " hit=" << *hit;
        if (end >= *r.t_ref - slack) continue;
        // Before a crossing the ray stays in for more than 4ε, a bracket (an
        // observed sign change) ending early is wrong; only the isolation's
        // tangent hits, where H is 0 to double precision, may come early.
        const bool crossing = (r.kind == RefKind::Simple || r.kind == RefKind::Multiple) &&
                              (!r.t_next || *r.t_next - *r.t_ref > 4.0 * eps);
        EXPECT_FALSE(crossing && !crossed.exact)
            << "a bracket ending before the first root: " << describe(r) << " hit=" << *hit;
        ++tally.tangent;
        expect_h_may_vanish();
    }
    for (const auto& [surface, t] : tallies)
        std::printf("sphere tracer, |x_d| = %g, on %-11s: %4d hits (%3d isolated in ε-segments), %3d tangent hits "
                    "early, %2d beyond the span\n",
                    s, surface.c_str(), t.hits, t.isolated, t.tangent, t.beyond_span);
}

struct StrictTally {
    int rays = 0, exact = 0, numerically_zero_early = 0;
    double worst_exact = 0.0;  // largest |t − t_ref| / scale among exact hits on well-conditioned roots
};

/// The guaranteed isolating methods on every ray of the suite:
/// - never a miss: every ray with a root gets a hit;
/// - never late: no hit beyond the first root by more than 1e-9 × scale — or,
///   for a root where |H′| < 1e-6 (a near-double root of a grazing ray), by
///   more than 1e-7 × scale: no evaluation of H in double precision places
///   such a root better than about (rounding error of H) / |H′|;
/// - otherwise exact, |t − t_ref| within that tolerance — except where a hit comes
///   earlier (or on a ray with no root) at a place where H cannot be told
///   from 0 in double precision: a ray grazing the surface closer than
///   rounding can resolve. There, the enclosure of H over the finest segment
///   at the hit must contain 0; such hits are counted and printed.
void expect_strict(Method method, double s) {
    std::map<std::string, std::unique_ptr<Tape>> tapes;
    std::map<std::string, StrictTally> tallies;
    for (const SuiteRay& r : suite()) {
        auto& tape = tapes[r.surface];
        if (!tape) tape = std::make_unique<Tape>(ray_suite_surface(r.surface).f);
        RayFunction h(*tape);
        h.set_ray(scaled_ray(r, s));
        TraceCounters counters;
        const RootFinderSettings settings = settings_for_scale(r.scale);
        HitResult hit = make_root_finder(method, *tape, settings)->first_hit(h, scaled_span(r, s), counters);
        if (hit.t) *hit.t *= s;
        StrictTally& t = tallies[r.surface];
        ++t.rays;
        const bool well_conditioned = r.kind == RefKind::Simple && r.slope >= 1e-6;
        const double tolerance = (well_conditioned ? 1e-9 : 1e-7) * r.scale;
        if (r.t_ref && !hit.t) {
            ADD_FAILURE() << method_name(method) << " missed: " << describe(r);
            continue;
        }
        if (!hit.t) continue;  // no root, no hit
        if (r.t_ref && *hit.t > *r.t_ref + tolerance) {
            ADD_FAILURE() << method_name(method) << " hit after the first root: " << describe(r) << " hit=" << *hit.t;
            continue;
        }
        if (r.t_ref && *hit.t >= *r.t_ref - tolerance) {
            ++t.exact;
            if (well_conditioned) t.worst_exact = std::max(t.worst_exact, std::abs(*hit.t - *r.t_ref) / r.scale);
            continue;
        }
        ++t.numerically_zero_early;
        RayFunction unscaled(*tape);
        unscaled.set_ray(r.ray);
        const Interval there = unscaled.enclose(*hit.t, *hit.t + settings.tangent_width, counters).v;
        EXPECT_TRUE(there.contains(0.0)) << method_name(method) << " hit early where H is not 0: " << describe(r)
                                         << " hit=" << *hit.t << " H in [" << there.lo << ", " << there.hi << "]";
    }
    for (const auto& [surface, t] : tallies)
        std::printf("%-8s |x_d| = %-5g on %-11s: %4d rays, 0 misses, %4d exact (worst simple root %.1e x scale), %3d "
                    "early where H is 0 to double precision\n",
                    std::string(method_name(method)).c_str(), s, surface.c_str(), t.rays, t.exact, t.worst_exact,
                    t.numerically_zero_early);
}

TEST_P(RaySuiteScaled, IntervalMethodNeverMissesAndIsExact) { expect_strict(Method::Interval, GetParam()); }
TEST_P(RaySuiteScaled, LgMethodNeverMissesAndIsExact) { expect_strict(Method::Lg, GetParam()); }
TEST_P(RaySuiteScaled, SphereMethodNeverMissesAndIsExact) { expect_strict(Method::Sphere, GetParam()); }

// A ray known to start outside (a later octree cell's) skips the start's
// evaluation: on every suite ray that starts outside, each guaranteed
// method's first_hit_from_outside gives first_hit's answer, bit for bit,
// with the same interval evaluations, and over the suite fewer point
// evaluations. Ray by ray the point evaluations may differ either way:
// RayFunction remembers its last two values, and the start's among them
// changes which later values are found there instead of taken again.
TEST(RaySuite, AStartKnownOutsideGivesTheSameHitForLessWork) {
    std::map<std::string, std::unique_ptr<Tape>> tapes;
    for (const Method method : {Method::Interval, Method::Lg, Method::Sphere}) {
        int outside = 0;
        std::int64_t saved = 0;  // point evaluations, over the suite
        for (const SuiteRay& r : suite()) {
            auto& tape = tapes[r.surface];
            if (!tape) tape = std::make_unique<Tape>(ray_suite_surface(r.surface).f);
            const auto finder = make_root_finder(method, *tape, settings_for_scale(r.scale));
            RayFunction h(*tape);
            h.set_ray(r.ray);
            TraceCounters full, from_outside, start;
            if (!(h.value(r.span.t0, start) > 0.0)) continue;
            ++outside;
            h.set_ray(r.ray);  // forgets the value just taken
            const HitResult a = finder->first_hit(h, r.span, full);
            h.set_ray(r.ray);
            const HitResult b = finder->first_hit_from_outside(h, r.span, from_outside);
            ASSERT_EQ(a.status, b.status) << method_name(method) << ": " << describe(r);
            ASSERT_EQ(a.t, b.t) << method_name(method) << ": " << describe(r);
            ASSERT_EQ(from_outside.interval_evaluations, full.interval_evaluations) << method_name(method);
            saved += static_cast<std::int64_t>(full.point_evaluations) -
                     static_cast<std::int64_t>(from_outside.point_evaluations);
        }
        EXPECT_GT(outside, 5000) << method_name(method);
        EXPECT_GT(saved, 0) << method_name(method);
        std::printf("%s: %d rays starting outside, %lld point evaluations saved\n", std::string(method_name(method)).c_str(),
                    outside, static_cast<long long>(saved));
    }
}

// The polynomial method on the suite's polynomial surfaces: no miss, no late
// hit, and an early hit (or one without a root) only where |H| is within
// twice its proven rounding bound B on the ray — where the arithmetic cannot
// tell H from 0 (trace/polynomial_method.hpp).
TEST_P(RaySuiteScaled, PolynomialMethodNeverMissesOnPolynomialSurfaces) {
    const double s = GetParam();
    std::map<std::string, std::unique_ptr<Tape>> tapes;
    int rays = 0, unresolved = 0;
    for (const SuiteRay& r : suite()) {
        auto& tape = tapes[r.surface];
        if (!tape) tape = std::make_unique<Tape>(ray_suite_surface(r.surface).f);
        if (!tape->is_polynomial()) continue;
        ++rays;
        const RootFinderSettings settings = settings_for_scale(r.scale);
        PolynomialMethod method(*tape, settings);
        RayFunction h(*tape);
        h.set_ray(scaled_ray(r, s));
        TraceCounters counters;
        HitResult hit = method.first_hit(h, scaled_span(r, s), counters);
        if (hit.t) *hit.t *= s;
        const bool well_conditioned = r.kind == RefKind::Simple && r.slope >= 1e-6;
        const double tolerance = (well_conditioned ? 1e-9 : 1e-7) * r.scale;
        if (r.t_ref && !hit.t) {
            ADD_FAILURE() << "polynomial missed: " << describe(r);
            continue;
        }
        if (!hit.t) continue;
        if (r.t_ref && *hit.t > *r.t_ref + tolerance) {
            ADD_FAILURE() << "polynomial hit after the first root: " << describe(r) << " hit=" << *hit.t;
            continue;
        }
        if (r.t_ref && *hit.t >= *r.t_ref - tolerance) continue;
        ++unresolved;
        RayFunction unscaled(*tape);
        unscaled.set_ray(r.ray);
        const double bound = method.rounding_bound(scaled_ray(r, s), scaled_span(r, s));
        EXPECT_LE(std::abs(unscaled.value(*hit.t, counters)), 2.0 * bound)
            << "polynomial hit early where H is not 0: " << describe(r) << " hit=" << *hit.t;
    }
    std::printf("polynomial |x_d| = %g: %d rays on polynomial surfaces, 0 misses, %d hits where |H| <= 2B\n", s, rays,
                unresolved);
    EXPECT_GT(rays, 2000);
}

std::string scale_name(const ::testing::TestParamInfo<double>& param) {
    constexpr std::array<const char*, direction_scales.size()> names{"unit", "times_0_37", "times_1e_3", "times_1e3"};
    return names[param.index];
}

INSTANTIATE_TEST_SUITE_P(DirectionLengths, RaySuiteScaled, ::testing::ValuesIn(direction_scales), scale_name);

}  // namespace
}  // namespace zeroset::test
