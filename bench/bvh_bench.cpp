// BVH kernels: building over N random boxes (the sphere field of
// bench/povray/sphere_field.py: N spheres in [-5, 5]³, radii ∝ N^(−1/3)),
// and traversing it with the primary rays of a 400×300 pinhole camera — a
// closest-hit walk where each box "hit" is its entry distance (no object
// behind it), so what is timed is the tree and nothing else.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "zeroset/accel/bvh.hpp"

namespace {

using zeroset::Box3;
using zeroset::Bvh;
using zeroset::Ray;
using zeroset::Vec3d;

std::vector<Box3> sphere_field(std::size_t n) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> position(-5.0, 5.0), radius(0.15, 0.35);
    const double scale = std::cbrt(1000.0 / static_cast<double>(n));
    std::vector<Box3> boxes;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3d c{position(random), position(random), position(random)};
        const double r = radius(random) * scale;
        boxes.push_back({c - Vec3d{r, r, r}, c + Vec3d{r, r, r}});
    }
    return boxes;
}

std::vector<Ray> camera_rays() {
    std::vector<Ray> rays;
    const double half = std::tan(20.0 * M_PI / 180.0);
    for (int py = 0; py < 300; py += 2)
        for (int px = 0; px < 400; px += 2) {
            const double sx = (2.0 * (px + 0.5) / 400.0 - 1.0) * half, sy = (1.0 - 2.0 * (py + 0.5) / 300.0) * half * 0.75;
            rays.push_back({{0, 0, -18}, zeroset::normalize(Vec3d{sx, sy, 1.0})});
        }
    return rays;
}

void BM_BvhBuild(benchmark::State& state) {
    const std::vector<Box3> boxes = sphere_field(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        Bvh bvh(boxes, static_cast<int>(state.range(1)));
        benchmark::DoNotOptimize(bvh.node_count());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BvhBuild)->ArgsProduct({{1000, 10000, 100000}, {1, 2}})->Unit(benchmark::kMillisecond);

void BM_BvhClosestHit(benchmark::State& state) {
    const std::vector<Box3> boxes = sphere_field(static_cast<std::size_t>(state.range(0)));
    const Bvh bvh(boxes, 1);
    const std::vector<Ray> rays = camera_rays();
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            double nearest = INFINITY;
            bvh.traverse(ray, 0.0, INFINITY, [&](std::uint32_t i, double t_max) {
                if (const auto span = boxes[i].clip(ray, 0.0, t_max)) nearest = std::min(nearest, span->t0);
                return std::min(t_max, nearest);
            });
            benchmark::DoNotOptimize(nearest);
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(rays.size()));
}
BENCHMARK(BM_BvhClosestHit)->Arg(10)->Arg(100)->Arg(1000)->Arg(4000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
