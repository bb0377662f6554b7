// The blob primitive's first hit along camera rays, without shading or
// threads: the kernel of issue 11's scale table and of POV-Ray's blob
// scenes. Two blobs of POV-Ray's kernel: POV-Ray's `blob1a.pov` (two
// crossed cylinders and a negative sphere, turned −30° about x, seen from
// its camera) and the 1 000-component cloud of bench/blobs/blob_scene.py's
// layout (seeded here, not the same draw). Each iteration traces a 128×128
// grid of rays over the scene's view; rays/s is the figure to compare.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace {

using zeroset::BlobComponent;
using zeroset::Vec3d;

/// A pinhole camera's rays over a side × side grid, looking from `eye` at the
/// origin with a vertical field of view of `fov` degrees.
std::vector<zeroset::Ray> camera_rays(const Vec3d& eye, double fov, int side) {
    const Vec3d forward = zeroset::normalize(-eye);
    const Vec3d right = zeroset::normalize(zeroset::cross(Vec3d{0, 1, 0}, forward));
    const Vec3d up = zeroset::cross(forward, right);
    const double half = std::tan(fov * M_PI / 360.0);
    std::vector<zeroset::Ray> rays;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const double sx = (2.0 * (x + 0.5) / side - 1.0) * half, sy = (1.0 - 2.0 * (y + 0.5) / side) * half;
            rays.push_back({eye, zeroset::normalize(forward + sx * right + sy * up)});
        }
    return rays;
}

std::vector<BlobComponent> crossed_cylinders() {
    const zeroset::Mat4 turn = zeroset::Mat4::rotate_xyz_degrees({-30, 0, 0});
    const auto at = [&](const Vec3d& p) { return turn.transform_point(p); };
    BlobComponent a, b, hole;
    a.center = at({-7, 0, 0});
    a.end = at({7, 0, 0});
    a.radius = 4;
    a.strength = 2;
    b.center = at({0, 0, -7});
    b.end = at({0, 0, 7});
    b.radius = 4;
    b.strength = 2;
    hole.center = at({0, 3, 0});
    hole.radius = 2.5;
    hole.strength = -4;
    return {a, b, hole};
}

std::vector<BlobComponent> cloud(int n) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> place(-5.0, 5.0), size(0.6, 0.9);
    const double scale = std::cbrt(1000.0 / n);
    std::vector<BlobComponent> components(static_cast<std::size_t>(n));
    for (BlobComponent& c : components) {
        c.center = {place(random), place(random), place(random)};
        c.radius = size(random) * scale;
    }
    return components;
}

void trace(benchmark::State& state, std::vector<BlobComponent> components, const Vec3d& eye, double fov) {
    const auto model = std::make_shared<const zeroset::BlobModel>(zeroset::BlobKernel::PovRay, 0.5, std::move(components));
    const zeroset::Blob blob(zeroset::BlobDescription{"bench", model, zeroset::no_material, 1e-9, 1});
    const std::vector<zeroset::Ray> rays = camera_rays(eye, fov, 128);
    zeroset::TraceScratch scratch(1);
    std::size_t hits = 0;
    for (auto _ : state) {
        hits = 0;
        for (const zeroset::Ray& ray : rays) hits += blob.first_hit(ray, 0.0, 1e9, scratch).has_value();
        benchmark::ClobberMemory();
    }
    state.counters["hits"] = static_cast<double>(hits);
    state.counters["rays/s"] = benchmark::Counter(static_cast<double>(rays.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_BlobCrossedCylinders(benchmark::State& state) { trace(state, crossed_cylinders(), {0, 8, -15}, 36); }
BENCHMARK(BM_BlobCrossedCylinders)->Unit(benchmark::kMillisecond);

void BM_BlobCloud1000(benchmark::State& state) { trace(state, cloud(1000), {0, 6, -18}, 50); }
BENCHMARK(BM_BlobCloud1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
