// Tile scheduling over std::threads and per-pixel work.
#include "zeroset/render/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "zeroset/render/camera_rays.hpp"
#include "zeroset/render/cone_tracer.hpp"
#include "zeroset/render/pixel_samples.hpp"
#include "zeroset/render/scene_tracer.hpp"
#include "zeroset/render/shading.hpp"

namespace zeroset {

namespace {

constexpr int tile_size = 16;
constexpr int max_samples_per_pixel = 1024;

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += tile_size)
        for (int x = 0; x < width; x += tile_size)
            tiles.push_back({x, y, std::min(x + tile_size, width), std::min(y + tile_size, height)});
    return tiles;
}

/// Per-thread totals, merged at the end.
struct ThreadTotals {
    RenderStats stats;
    ShadingCounters shading;
    ConeCounters cone;
    std::optional<TraceScratch::NanRecord> first_nan;
    std::optional<std::pair<int, int>> non_finite_pixel;  // the first pixel whose colour overflowed
    std::uint64_t evaluations_counted = 0;                // of this thread's, added to the shared total
};

/// What the threads share to stop early: the evaluations spent against the
/// budget, and whether any thread has met a reason to stop (a NaN, the
/// budget spent) — the render's result is an error then, and the rest of
/// the image is not worth tracing.
struct StopSignal {
    std::uint64_t budget = 0;
    std::uint64_t threads = 1;
    std::atomic<std::uint64_t> spent{0};
    std::atomic<bool> over_budget{false};
    std::atomic<bool> stop{false};

    /// A thread's allowance until its next report: its share of what is
    /// left, so that the threads together stay within the budget while
    /// their queries run (TraceCounters::evaluation_limit).
    void allow(SceneTracer& tracer, std::uint64_t total) const {
        const std::uint64_t left = budget - std::min(total, budget);
        tracer.counters().evaluation_limit = tracer.counters().evaluations() + left / threads;
    }

    /// Adds the thread's evaluations since its last report, after every
    /// pixel. A thread past its allowance has had queries fail, so the
    /// render is over budget even if the others left some unspent.
    void report(SceneTracer& tracer, ThreadTotals& totals) {
        const std::uint64_t now = tracer.counters().evaluations();
        const std::uint64_t since = now - totals.evaluations_counted;
        const std::uint64_t total = spent.fetch_add(since) + since;
        totals.evaluations_counted = now;
        if (total > budget || tracer.counters().over_limit()) over_budget = true;
        if (over_budget || tracer.first_nan()) stop = true;
        allow(tracer, total);
    }
};

/// What a pixel's samples saw nearest: for the image's depth and normal layers.
struct NearestSample {
    float depth = std::numeric_limits<float>::infinity();
    Vec3f normal{0, 0, 0};

    void offer(const SurfaceHit& hit) {
        if (!(hit.t < depth)) return;
        depth = static_cast<float>(hit.t);
        normal = {static_cast<float>(hit.normal.x), static_cast<float>(hit.normal.y), static_cast<float>(hit.normal.z)};
    }
};

/// The tile's pixels; with a cone tracer, each pixel's one ray is widened
/// to its footprint's cone, whose edges are blended over what the ray sees.
void render_tile(const Tile& tile, const Scene& scene, const CameraRays& camera, int spp, SceneTracer& tracer,
                 ConeTracer* cone, Image& image, ThreadTotals& totals, StopSignal& signal) {
    constexpr double far = std::numeric_limits<double>::infinity();
    const bool layers = image.has_layers();
    for (int py = tile.y0; py < tile.y1; ++py) {
        for (int px = tile.x0; px < tile.x1; ++px) {
            if (signal.stop.load(std::memory_order_relaxed)) return;
            Vec3d sum{};
            NearestSample nearest;
            for (int s = 0; s < spp; ++s) {
                const SubPixel sub = pixel_sample(px, py, s, spp);
                const Ray ray = camera.ray(px, py, sub.x, sub.y);
                ++totals.stats.camera_rays;
                const auto hit = tracer.closest_hit(ray, far);
                Vec3d seen = scene.background;
                if (hit) {
                    ++totals.stats.hits;
                    nearest.offer(*hit);
                    seen = shade(tracer, ray, *hit, totals.shading, scene.image.reflection_depth);
                }
                if (cone)
                    seen = cone->pixel(tracer, ray, hit, seen, totals.shading, scene.image.reflection_depth,
                                       totals.cone);
                sum += seen;
            }
            const Vec3d c = sum / static_cast<double>(spp);
            const Vec3f pixel{static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)};
            if (!(std::isfinite(pixel.x) && std::isfinite(pixel.y) && std::isfinite(pixel.z)) &&
                !totals.non_finite_pixel)
                totals.non_finite_pixel = {px, py};
            image.at(px, py) = pixel;
            if (layers) {
                const std::size_t i = static_cast<std::size_t>(py) * static_cast<std::size_t>(image.width) +
                                      static_cast<std::size_t>(px);
                image.depth[i] = nearest.depth;
                image.normals[i] = nearest.normal;
            }
            signal.report(tracer, totals);
        }
    }
}

void check_camera(const Camera& camera) {
    const Vec3d view = camera.at - camera.from;
    if (!(length(view) > 0.0)) throw RenderError("the camera's `from` and `at` are the same point");
    if (!(length(cross(camera.up, view)) > 1e-12 * length(view) * length(camera.up)))
        throw RenderError("the camera's `up` is parallel to its view direction");
}

std::string budget_message(std::uint64_t budget, bool by_default) {
    std::ostringstream message;
    message << "the render was stopped when it had spent its budget of " << budget << " evaluations of the surfaces";
    if (by_default)
        message << " (" << evaluations_per_camera_ray << " per camera ray, at least " << least_evaluation_budget << ")";
    message << ": an object is far too costly for its method here — a surface with detail finer than a pixel "
               "everywhere, say, or bounds far larger than the surface. Try another method or tighter bounds, or "
               "raise the budget (--max-evaluations)";
    return message.str();
}

}  // namespace

std::uint64_t default_evaluation_budget(const RenderSettings& settings) {
    const auto rays = static_cast<std::uint64_t>(settings.width) * static_cast<std::uint64_t>(settings.height) *
                      static_cast<std::uint64_t>(std::max(1, settings.samples_per_pixel));
    return std::max(least_evaluation_budget, rays * evaluations_per_camera_ray);
}

void require_in_range(int value, int low, int high, const char* what) {
    if (value >= low && value <= high) return;
    std::ostringstream message;
    message << what << " must be between " << low << " and " << high << ", got " << value;
    throw RenderError(message.str());
}

void require_image_fits(int width, int height) {
    const long long pixels = static_cast<long long>(width) * height;
    if (pixels <= max_image_pixels) return;
    std::ostringstream message;
    message.precision(3);
    message << width << "x" << height << " is " << pixels << " pixels, which would take "
            << static_cast<double>(pixels) * 15.0 / (1 << 30) << " GiB; at most " << max_image_pixels
            << " pixels (e.g. 16384x16384) are rendered";
    throw RenderError(message.str());
}

void validate(const RenderSettings& s) {
    require_in_range(s.width, 1, max_image_side, "width");
    require_in_range(s.height, 1, max_image_side, "height");
    require_image_fits(s.width, s.height);
    require_in_range(s.samples_per_pixel, 1, max_samples_per_pixel, "samples per pixel");
    if (s.cone_antialiasing && s.samples_per_pixel != 1)
        throw RenderError("cone antialiasing traces one ray per pixel: give it 1 sample per pixel, not " +
                          std::to_string(s.samples_per_pixel) + " (or antialias by samples alone)");
    require_in_range(s.threads, 0, 4096, "threads");
    if (s.max_evaluations && *s.max_evaluations == 0) throw RenderError("the evaluation budget (--max-evaluations) must be at least 1");
}

RenderResult render(const Scene& scene, const RenderSettings& settings) {
    validate(settings);
    check_camera(scene.camera);
    require_in_range(scene.image.reflection_depth, 0, max_reflection_depth, "the reflection depth");
    const auto start = std::chrono::steady_clock::now();

    const PreparedScene prepared(scene, {settings.method, settings.solver, settings.normals, settings.partition,
                                         settings.width, settings.height, settings.on_prepare_progress});
    const CameraRays camera(scene.camera, settings.width, settings.height);
    const std::optional<SceneDistance> distance =
        settings.cone_antialiasing ? std::optional<SceneDistance>(scene) : std::nullopt;
    const double prepare_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height);
    const int thread_count = settings.threads > 0
                                 ? settings.threads
                                 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

    RenderResult result{Image(settings.width, settings.height), {}};
    if (settings.layers) result.image.add_layers();
    std::vector<ThreadTotals> totals(static_cast<std::size_t>(thread_count));
    std::atomic<std::size_t> next_tile{0};
    std::mutex progress_mutex;
    int tiles_done = 0;
    StopSignal signal;
    signal.budget = settings.max_evaluations.value_or(default_evaluation_budget(settings));
    signal.threads = static_cast<std::uint64_t>(thread_count);

    const auto worker = [&](ThreadTotals& mine) {
        SceneTracer tracer(prepared);
        std::optional<ConeTracer> cone;
        if (distance) cone.emplace(*distance, camera.footprint_radius());
        signal.allow(tracer, signal.spent);
        for (std::size_t i = next_tile++; i < tiles.size(); i = next_tile++) {
            render_tile(tiles[i], scene, camera, settings.samples_per_pixel, tracer, cone ? &*cone : nullptr,
                        result.image, mine, signal);
            if (settings.on_progress) {
                std::lock_guard lock(progress_mutex);
                settings.on_progress(++tiles_done, static_cast<int>(tiles.size()));
            }
        }
        mine.first_nan = tracer.first_nan();
        mine.stats.counters += tracer.counters();
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < thread_count; ++t) pool.emplace_back(worker, std::ref(totals[static_cast<std::size_t>(t)]));
        worker(totals[0]);
    }

    RenderStats& stats = result.stats;
    for (const ThreadTotals& t : totals) {
        stats.camera_rays += t.stats.camera_rays;
        stats.hits += t.stats.hits;
        stats.shadow_rays += t.shading.shadow_rays;
        stats.reflection_rays += t.shading.reflection_rays;
        stats.counters += t.stats.counters;
        stats.cone += t.cone;
        if (t.first_nan) throw RenderError(nan_message(*t.first_nan));
    }
    if (signal.over_budget) throw RenderError(budget_message(signal.budget, !settings.max_evaluations));
    for (const ThreadTotals& t : totals) {
        if (!t.non_finite_pixel) continue;
        const auto [px, py] = *t.non_finite_pixel;
        throw RenderError("pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                          ") has no finite colour: light and material colours multiply past the largest float "
                          "(3.4e38), or a material's colour pattern is NaN or infinite there; scale the colours down "
                          "or fix the pattern");
    }
    stats.width = settings.width;
    stats.height = settings.height;
    stats.samples_per_pixel = settings.samples_per_pixel;
    stats.cone_antialiasing = settings.cone_antialiasing;
    stats.threads = thread_count;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.prepare_seconds = prepare_seconds;
    stats.methods = prepared.method_counts();
    stats.partitions = prepared.partition_summary();
    stats.blobs = prepared.blob_summary();
    stats.warnings = scene.warnings;
    stats.warnings.insert(stats.warnings.end(), prepared.warnings().begin(), prepared.warnings().end());
    return result;
}

}  // namespace zeroset
