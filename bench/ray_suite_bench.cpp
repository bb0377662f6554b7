// Every ray-intersection method on the ray suite (tests/data/ray_suite.tsv,
// 11 054 rays with MPFI first-hit references): time per ray, evaluations per
// ray, and how often it misses the first root or reports one where none is.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "support/ray_suite.hpp"
#include "support/ray_suite_surfaces.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace {

using namespace zeroset;
using zeroset::test::SuiteRay;

const std::vector<SuiteRay>& suite() {
    static const auto rays = zeroset::test::load_ray_suite(ZEROSET_SOURCE_DIR "/tests/data/ray_suite.tsv");
    return rays;
}

/// One tape, evaluator set and method per surface, built before timing.
struct Prepared {
    std::unique_ptr<Tape> tape;
    std::unique_ptr<RayFunction> h;
    std::unique_ptr<RootFinder> finder;
};

void BM_RaySuite(benchmark::State& state, Method method) {
    std::map<std::string, Prepared> prepared;
    for (const SuiteRay& r : suite()) {
        Prepared& p = prepared[r.surface];
        if (p.tape) continue;
        p.tape = std::make_unique<Tape>(zeroset::test::ray_suite_surface(r.surface).f);
        p.h = std::make_unique<RayFunction>(*p.tape);
        p.finder = make_root_finder(method, *p.tape, settings_for_scale(r.scale));
    }
    std::uint64_t evaluations = 0, misses = 0, false_hits = 0, rays = 0;
    for (auto _ : state) {
        evaluations = misses = false_hits = rays = 0;
        for (const SuiteRay& r : suite()) {
            Prepared& p = prepared[r.surface];
            p.h->set_ray(r.ray);
            TraceCounters counters;
            const HitResult hit = p.finder->first_hit(*p.h, r.span, counters);
            evaluations += counters.evaluations();
            ++rays;
            if (r.t_ref && (!hit.t || *hit.t > *r.t_ref + 1e-7 * r.scale)) ++misses;
            if (!r.t_ref && hit.t) ++false_hits;
        }
    }
    const double n = static_cast<double>(rays);
    state.counters["miss_%"] = 100.0 * static_cast<double>(misses) / n;
    state.counters["false_hit_%"] = 100.0 * static_cast<double>(false_hits) / n;
    state.counters["evals/ray"] = static_cast<double>(evaluations) / n;
    state.counters["s/ray"] = benchmark::Counter(n * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(BM_RaySuite, interval, zeroset::Method::Interval)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RaySuite, lg, zeroset::Method::Lg)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RaySuite, sphere, zeroset::Method::Sphere)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RaySuite, newton, zeroset::Method::Newton)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RaySuite, regula_falsi, zeroset::Method::RegulaFalsi)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RaySuite, bisection, zeroset::Method::Bisection)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
