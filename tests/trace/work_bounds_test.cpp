// The per-query work bounds (root_finder.hpp): with max_segments at the
// number of segments a ray needs the hit is found, one below the method gives
// up with status Failed instead of answering wrongly — and never runs on;
// all_hits collects max_hits roots, and gives up on a ray with more.
#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

TEST(WorkBounds, EverySubdividingMethodGivesUpPastMaxSegments) {
    const Expr x = var_x(), y = var_y(), z = var_z();
    const Tape tape(square(x) + square(y) + square(z) - 1.0);
    const Bounds bounds = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
    const Ray ray{{-3, 0.999, 0}, {1, 0, 0}};  // a near graze: many segments to isolate it
    const Span span = *bounds.clip(ray, 0.0, INFINITY);
    const double expected = 3.0 - std::sqrt(1.0 - 0.999 * 0.999);
    for (const Method method : {Method::Interval, Method::Lg, Method::Sphere}) {
        const auto run = [&](long max_segments) {
            RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
            settings.max_segments = max_segments;
            RayFunction h(tape);
            h.set_ray(ray);
            TraceCounters counters;
            return make_root_finder(method, tape, settings)->first_hit(h, span, counters);
        };
        long needed = 1;
        while (needed < 100000 && run(needed).status != HitStatus::Ok) needed *= 2;
        long lo = needed / 2, hi = needed;  // run(lo) gave up, run(hi) did not
        while (hi - lo > 1) {
            const long mid = (lo + hi) / 2;
            (run(mid).status == HitStatus::Ok ? hi : lo) = mid;
        }
        const HitResult at = run(hi), below = run(hi - 1);
        EXPECT_GE(hi, 2) << method_name(method) << ": the ray needs more than one segment";
        EXPECT_EQ(at.status, HitStatus::Ok) << method_name(method);
        EXPECT_NEAR(at.t.value_or(NAN), expected, 1e-12) << method_name(method);
        EXPECT_EQ(below.status, HitStatus::Failed) << method_name(method) << " with " << hi - 1 << " segments";
        EXPECT_FALSE(below.t.has_value()) << method_name(method);
    }
}

// The renderer's budget reaches into a query: past the counters' limit the
// next segment gives up.
TEST(WorkBounds, EverySubdividingMethodGivesUpPastTheEvaluationLimit) {
    const Tape tape(square(var_x()) + square(var_y()) + square(var_z()) - 1.0);
    const Bounds bounds = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
    const Ray ray{{-3, 0.999, 0}, {1, 0, 0}};
    const Span span = *bounds.clip(ray, 0.0, INFINITY);
    for (const Method method : {Method::Interval, Method::Lg, Method::Sphere}) {
        const auto run = [&](std::uint64_t limit, TraceCounters& counters) {
            RayFunction h(tape);
            h.set_ray(ray);
            counters.evaluation_limit = limit;
            return make_root_finder(method, tape, settings_for_scale(bounds.box.diagonal()))->first_hit(h, span, counters);
        };
        TraceCounters free, limited;
        EXPECT_EQ(run(std::numeric_limits<std::uint64_t>::max(), free).status, HitStatus::Ok) << method_name(method);
        ASSERT_GT(free.evaluations(), 20U) << method_name(method);
        EXPECT_EQ(run(10, limited).status, HitStatus::Failed) << method_name(method);
        EXPECT_LT(limited.evaluations(), 30U) << method_name(method) << ": one segment past the limit at most";
    }
}

TEST(WorkBounds, AllHitsGivesUpPastMaxHits) {
    const Tape tape(sin(var_x()));
    const Bounds bounds = Bounds::make_box({{-100, -1, -1}, {100, 1, 1}});
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    const Span span{0.5, 10.5 * M_PI};  // the roots π, 2π, …, 10π
    for (const Method method : {Method::Interval, Method::Lg, Method::Sphere, Method::RegulaFalsi, Method::Bisection}) {
        const auto run = [&](std::size_t max_hits, std::vector<double>& hits) {
            RootFinderSettings settings = settings_for_scale(bounds.box.diagonal());
            settings.max_hits = max_hits;
            RayFunction h(tape);
            h.set_ray(ray);
            TraceCounters counters;
            return make_root_finder(method, tape, settings)->all_hits(h, span, hits, counters);
        };
        std::vector<double> at, below;
        EXPECT_EQ(run(10, at), HitStatus::Ok) << method_name(method);
        ASSERT_EQ(at.size(), 10U) << method_name(method);
        for (std::size_t k = 0; k < at.size(); ++k)
            EXPECT_NEAR(at[k], static_cast<double>(k + 1) * M_PI, 1e-9) << method_name(method);
        EXPECT_EQ(run(9, below), HitStatus::Failed) << method_name(method);
        EXPECT_EQ(below.size(), 9U) << method_name(method) << ": the roots found up to the cap are kept";
    }
}

}  // namespace
}  // namespace zeroset
