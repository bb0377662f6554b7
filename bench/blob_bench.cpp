// The blob primitive's first hit along camera rays, without shading or
// threads: the kernel of issue 11's scale table and of POV-Ray's blob
// scenes. Two blobs of POV-Ray's kernel: POV-Ray's `blob1a.pov` (two
// crossed cylinders and a negative sphere, turned −30° about x, seen from
// its camera) and the 1 000-component cloud of bench/blobs/blob_scene.py's
// layout (seeded here, not the same draw). Each iteration traces an eighth
// of a 512×512 image's camera rays (32 768), with their tiles' frusta (tiles:1,
// as the renderer's camera rays) or without (tiles:0: the BVH's walk);
// rays/s is the figure to compare. The cloud's shadow rays (from those
// rays' hits towards the light) are timed on their own.
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

/// A pinhole camera looking from `eye` at the origin with a vertical field
/// of view of `fov` degrees, over a side × side image in 16 × 16 tiles (what
/// the renderer hands a blob with a camera ray): every eighth tile's rays,
/// in a diagonal pattern over the whole view, each tile after its frustum.
struct TiledRays {
    std::vector<zeroset::Ray> rays;
    std::vector<zeroset::CameraFrustum> tiles;  // tile k holds rays[256·k, 256·(k + 1))
};

TiledRays camera_rays(const Vec3d& eye, double fov, int side) {
    constexpr int tile_side = 16;
    const Vec3d forward = zeroset::normalize(-eye);
    const Vec3d right = zeroset::normalize(zeroset::cross(Vec3d{0, 1, 0}, forward));
    const Vec3d up = zeroset::cross(forward, right);
    const double half = std::tan(fov * M_PI / 360.0), step = 2.0 * half / side;
    TiledRays out;
    for (int ty = 0; ty < side; ty += tile_side)
        for (int tx = 0; tx < side; tx += tile_side) {
            if ((tx + ty) / tile_side % 8 != 0) continue;
            zeroset::CameraFrustum f{eye, forward, right, up, -half + tx * step, step, half - ty * step, -step,
                                     tile_side, tile_side};
            out.tiles.push_back(f);
            for (int y = ty; y < ty + tile_side; ++y)
                for (int x = tx; x < tx + tile_side; ++x)
                    out.rays.push_back({eye, zeroset::normalize(forward + (f.u0 + (x - tx + 0.5) * step) * right +
                                                                (f.v0 - (y - ty + 0.5) * step) * up)});
        }
    return out;
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

/// Traces the blob's first hit along every ray; with `tiles`, each ray
/// comes with its tile's frustum as a camera ray does.
void trace(benchmark::State& state, std::vector<BlobComponent> components, const Vec3d& eye, double fov) {
    const bool tiles = state.range(0) != 0;
    const auto model = std::make_shared<const zeroset::BlobModel>(zeroset::BlobKernel::PovRay, 0.5, std::move(components));
    const zeroset::Blob blob(zeroset::BlobDescription{"bench", model, zeroset::no_material, 1e-9, 1});
    const TiledRays camera = camera_rays(eye, fov, 512);
    zeroset::TraceScratch scratch(1);
    std::size_t hits = 0;
    zeroset::TraceCounters spent;
    for (auto _ : state) {
        hits = 0;
        const zeroset::TraceCounters before = scratch.counters;
        for (std::size_t i = 0; i < camera.rays.size(); ++i) {
            scratch.camera_frustum = tiles ? &camera.tiles[i / 256] : nullptr;
            hits += blob.first_hit(camera.rays[i], 0.0, 1e9, scratch).has_value();
        }
        scratch.camera_frustum = nullptr;
        spent = scratch.counters.since(before);
        benchmark::ClobberMemory();
    }
    const auto per_ray = [&](std::uint64_t count) { return static_cast<double>(count) / static_cast<double>(camera.rays.size()); };
    state.counters["hits"] = static_cast<double>(hits);
    state.counters["components/ray"] = per_ray(spent.blob_kernels);
    state.counters["evaluations/ray"] = per_ray(spent.evaluations());
    state.counters["rays/s"] =
        benchmark::Counter(static_cast<double>(camera.rays.size()), benchmark::Counter::kIsIterationInvariantRate);
}

/// Whether the shadow rays toward `light` from the camera rays' hits (each
/// started a hair off the surface, as shading does) are blocked.
void shadows(benchmark::State& state, std::vector<BlobComponent> components, const Vec3d& eye, double fov,
             const Vec3d& light) {
    const auto model = std::make_shared<const zeroset::BlobModel>(zeroset::BlobKernel::PovRay, 0.5, std::move(components));
    const zeroset::Blob blob(zeroset::BlobDescription{"bench", model, zeroset::no_material, 1e-9, 1});
    zeroset::TraceScratch scratch(1);
    std::vector<zeroset::Ray> rays;
    std::vector<double> lengths;
    for (const zeroset::Ray& ray : camera_rays(eye, fov, 512).rays)
        if (const auto hit = blob.first_hit(ray, 0.0, 1e9, scratch)) {
            const Vec3d p = ray.at(hit->t);
            const Vec3d normal = blob.local_normal(hit->surface, scratch);
            const Vec3d origin = p + normal * (1e-4 * blob.bounds().diagonal());
            rays.push_back({origin, zeroset::normalize(light - origin)});
            lengths.push_back(zeroset::length(light - origin));
        }
    std::size_t blocked = 0;
    zeroset::TraceCounters spent;
    for (auto _ : state) {
        blocked = 0;
        const zeroset::TraceCounters before = scratch.counters;
        for (std::size_t i = 0; i < rays.size(); ++i) blocked += blob.occluded(rays[i], 0.0, lengths[i], scratch);
        spent = scratch.counters.since(before);
        benchmark::ClobberMemory();
    }
    const auto per_ray = [&](std::uint64_t count) { return static_cast<double>(count) / static_cast<double>(rays.size()); };
    state.counters["blocked"] = static_cast<double>(blocked) / static_cast<double>(rays.size());
    state.counters["components/ray"] = per_ray(spent.blob_kernels);
    state.counters["evaluations/ray"] = per_ray(spent.evaluations());
    state.counters["rays/s"] = benchmark::Counter(static_cast<double>(rays.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_BlobCrossedCylinders(benchmark::State& state) { trace(state, crossed_cylinders(), {0, 8, -15}, 36); }
BENCHMARK(BM_BlobCrossedCylinders)->ArgName("tiles")->Arg(0)->Unit(benchmark::kMillisecond);

void BM_BlobCloud1000(benchmark::State& state) { trace(state, cloud(1000), {0, 6, -18}, 50); }
BENCHMARK(BM_BlobCloud1000)->ArgName("tiles")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_BlobCloud1000Shadows(benchmark::State& state) { shadows(state, cloud(1000), {0, 6, -18}, 50, {-20, 25, -15}); }
BENCHMARK(BM_BlobCloud1000Shadows)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
