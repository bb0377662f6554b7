// Per-pixel work of a tile, and the early stop shared by a frame's workers.
#include "zeroset/render/frame_render.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "zeroset/render/pixel_samples.hpp"
#include "zeroset/render/shading.hpp"

namespace zeroset {

namespace {

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

/// Writes a pixel's colour, and what its samples saw nearest where `into`
/// has layers, at (ix, iy) of `into`. False when the colour is not finite.
bool store_pixel(Image& into, int ix, int iy, const Vec3d& color, const NearestSample& nearest) {
    const Vec3f pixel{static_cast<float>(color.x), static_cast<float>(color.y), static_cast<float>(color.z)};
    into.at(ix, iy) = pixel;
    if (into.has_layers()) {
        const std::size_t i = static_cast<std::size_t>(iy) * static_cast<std::size_t>(into.width) + static_cast<std::size_t>(ix);
        into.depth[i] = nearest.depth;
        into.normals[i] = nearest.normal;
    }
    return std::isfinite(pixel.x) && std::isfinite(pixel.y) && std::isfinite(pixel.z);
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

/// Checks, then prepares: the settings and camera before any costly work.
const RenderSettings& checked(const Scene& scene, const RenderSettings& settings) {
    validate(settings);
    check_camera(scene.camera);
    require_in_range(scene.image.reflection_depth, 0, max_reflection_depth, "the reflection depth");
    return settings;
}

}  // namespace

std::size_t tile_count(int width, int height) {
    const auto columns = static_cast<std::size_t>((width + tile_side - 1) / tile_side);
    const auto rows = static_cast<std::size_t>((height + tile_side - 1) / tile_side);
    return columns * rows;
}

TileRect tile_at(int width, int height, std::size_t index) {
    const auto columns = static_cast<std::size_t>((width + tile_side - 1) / tile_side);
    const int x = static_cast<int>(index % columns) * tile_side, y = static_cast<int>(index / columns) * tile_side;
    return {x, y, std::min(x + tile_side, width), std::min(y + tile_side, height)};
}

std::vector<TileRect> image_tiles(int width, int height) {
    std::vector<TileRect> tiles;
    for (std::size_t i = 0; i < tile_count(width, height); ++i) tiles.push_back(tile_at(width, height, i));
    return tiles;
}

TileWork& TileWork::operator+=(const TileWork& o) {
    camera_rays += o.camera_rays, untraced_camera_rays += o.untraced_camera_rays, hits += o.hits;
    shadow_rays += o.shadow_rays, reflection_rays += o.reflection_rays;
    trace += o.trace;
    cone += o.cone;
    seconds += o.seconds;
    return *this;
}

FrameRender::FrameRender(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_(checked(scene, settings)),
      prepared_(scene, {settings.method, settings.solver, settings.normals, settings.partition, settings.width,
                        settings.height, settings.on_prepare_progress}),
      camera_(scene.camera, settings.width, settings.height),
      tiles_(image_tiles(settings.width, settings.height)),
      budget_(settings.max_evaluations.value_or(default_evaluation_budget(settings))) {
    if (settings.cone_antialiasing) distance_.emplace(scene);
    // The tiles go with the camera rays to the objects that use them: the
    // partitioned ones cull them, polynomial ones prove them empty, blobs
    // list their components by them.
    cull_camera_tiles_ = settings.frustum_culling &&
                         (prepared_.has_blobs() ||
                          std::any_of(prepared_.leaves().begin(), prepared_.leaves().end(), [](const ImplicitLeaf* leaf) {
                              return leaf->octree() != nullptr || leaf->proves_camera_tiles();
                          }));
    prepare_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count();
}

FrameRender::~FrameRender() = default;

FrameRender::Worker::Worker(FrameRender& frame, int threads_sharing_the_budget)
    : tracer_(frame.prepared_), threads_(static_cast<std::uint64_t>(std::max(1, threads_sharing_the_budget))) {
    if (frame.distance_) cone_.emplace(*frame.distance_, frame.camera_.footprint_radius());
    frame.allow(*this, frame.spent_);
}

/// A worker's allowance until its next report: its share of what is left,
/// so that the workers together stay within the budget while their queries
/// run (TraceCounters::evaluation_limit).
void FrameRender::allow(Worker& worker, std::uint64_t total) const {
    const std::uint64_t left = budget_ - std::min(total, budget_);
    worker.tracer_.counters().evaluation_limit = worker.tracer_.counters().evaluations() + left / worker.threads_;
}

/// Adds the worker's evaluations since its last report. A worker past its
/// allowance has had queries fail, so the render is over budget even if the
/// others left some unspent. Reporting every pixel cost 1–2 % of a render
/// (the shared total's cache line moving between cores); the allowance
/// keeps each worker within budget between reports.
void FrameRender::report(Worker& worker, bool flush) {
    const TraceCounters& counters = worker.tracer_.counters();
    const std::uint64_t now = counters.evaluations();
    const std::uint64_t since = now - worker.evaluations_reported_;
    if (!flush && since < report_interval && !counters.over_limit() && !worker.tracer_.first_nan()) return;
    const std::uint64_t total = spent_.fetch_add(since) + since;
    worker.evaluations_reported_ = now;
    if (total > budget_ || counters.over_limit()) stop_over_budget();
    if (const auto& nan = worker.tracer_.first_nan()) record_nan(*nan);
    allow(worker, total);
}

void FrameRender::stop_over_budget() {
    over_budget_ = true;
    stop_ = true;
}

void FrameRender::record_nan(const TraceScratch::NanRecord& nan) {
    std::lock_guard lock(failure_mutex_);
    if (!nan_failure_) nan_failure_ = nan_message(nan);
    stop_ = true;
}

void FrameRender::record_non_finite(int px, int py) {
    std::lock_guard lock(failure_mutex_);
    if (!non_finite_failure_)
        non_finite_failure_ = "pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                              ") has no finite colour: light and material colours multiply past the largest float "
                              "(3.4e38), or a material's colour pattern is NaN or infinite there; scale the colours "
                              "down or fix the pattern";
    stop_ = true;
}

std::optional<std::string> FrameRender::failure() const {
    std::lock_guard lock(failure_mutex_);
    if (nan_failure_) return nan_failure_;
    if (over_budget_) return budget_message(budget_, !settings_.max_evaluations);
    return non_finite_failure_;
}

// Every pixel gets what the traced loop would give it with no hit — its
// samples' background averaged, summed in the same order — pixel by pixel
// as that loop goes (it stops where the render stops, and counts the rays
// it would have made), without making the rays (each ~12 ns; most of an
// empty frame's time).
void FrameRender::fill_with_background(const TileRect& tile, Image& into, int origin_x, int origin_y, TileWork& work) {
    const int spp = settings_.samples_per_pixel;
    Vec3d sum{};
    for (int s = 0; s < spp; ++s) sum += scene_.background;
    const Vec3d color = sum / static_cast<double>(spp);
    const NearestSample none;
    for (int py = tile.y0; py < tile.y1; ++py)
        for (int px = tile.x0; px < tile.x1; ++px) {
            if (stopped()) break;
            work.camera_rays += static_cast<std::uint64_t>(spp);
            work.untraced_camera_rays += static_cast<std::uint64_t>(spp);
            if (!store_pixel(into, px - origin_x, py - origin_y, color, none)) record_non_finite(px, py);
        }
}

TileWork FrameRender::render_tile(std::size_t index, Worker& worker, Image& into, int origin_x, int origin_y) {
    const auto start = std::chrono::steady_clock::now();
    constexpr double far = std::numeric_limits<double>::infinity();
    const TileRect& tile = tiles_[index];
    const int spp = settings_.samples_per_pixel;
    SceneTracer& tracer = worker.tracer_;
    ConeTracer* cone = worker.cone_ ? &*worker.cone_ : nullptr;
    const TraceCounters before = tracer.counters();
    ShadingCounters shading;
    TileWork work;
    const CameraFrustum frustum = camera_.frustum(tile.x0, tile.y0, tile.x1, tile.y1);
    const CameraFrustum* culled = cull_camera_tiles_ ? &frustum : nullptr;
    // A tile proven to see no surface is the background, untraced. (Cone
    // tracing looks beside a ray that misses, so it keeps every ray.)
    const bool skips_empty_tiles = !cone && settings_.frustum_culling;
    if (skips_empty_tiles && tracer.misses_tile(frustum, false)) {
        fill_with_background(tile, into, origin_x, origin_y, work);
        report(worker, true);  // as every tile ends: the worker's allowance follows the frame's total
        work.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return work;
    }
    for (int py = tile.y0; py < tile.y1; ++py) {
        for (int px = tile.x0; px < tile.x1; ++px) {
            if (stopped()) break;
            Vec3d sum{};
            NearestSample nearest;
            for (int s = 0; s < spp; ++s) {
                const SubPixel sub = pixel_sample(px, py, s, spp);
                const Ray ray = camera_.ray(px, py, sub.x, sub.y);
                ++work.camera_rays;
                const int pixel = (py - tile.y0) * frustum.columns + (px - tile.x0);
                const auto hit = tracer.closest_hit(ray, far, culled, pixel);
                Vec3d seen = scene_.background;
                if (hit) {
                    ++work.hits;
                    nearest.offer(*hit);
                    seen = shade(tracer, ray, *hit, shading, scene_.image.reflection_depth);
                }
                if (cone)
                    seen = cone->pixel(tracer, ray, hit, seen, shading, scene_.image.reflection_depth, work.cone);
                sum += seen;
            }
            if (!store_pixel(into, px - origin_x, py - origin_y, sum / static_cast<double>(spp), nearest))
                record_non_finite(px, py);
            report(worker, false);
        }
        // Its rays all missed so far: it may be proven empty by now (a
        // polynomial leaf proves a tile after a few costly misses, or when
        // asked again). Asked after rows 1, 2, 4 and 8: each ask walks the
        // objects the tile sees.
        const int rows_done = py + 1 - tile.y0;
        if (skips_empty_tiles && work.hits == 0 && py + 1 < tile.y1 && std::has_single_bit(static_cast<unsigned>(rows_done)) &&
            tracer.misses_tile(frustum, true)) {
            fill_with_background({tile.x0, py + 1, tile.x1, tile.y1}, into, origin_x, origin_y, work);
            break;
        }
    }
    report(worker, true);
    work.shadow_rays = shading.shadow_rays;
    work.reflection_rays = shading.reflection_rays;
    work.trace = tracer.counters().since(before);
    work.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return work;
}

RenderStats FrameRender::finish(const TileWork& all_tiles, int threads, double seconds) const {
    if (auto why = failure()) throw RenderError(*why);
    RenderStats stats;
    stats.camera_rays = all_tiles.camera_rays;
    stats.untraced_camera_rays = all_tiles.untraced_camera_rays;
    stats.hits = all_tiles.hits;
    stats.shadow_rays = all_tiles.shadow_rays;
    stats.reflection_rays = all_tiles.reflection_rays;
    stats.counters = all_tiles.trace;
    stats.cone = all_tiles.cone;
    stats.width = settings_.width;
    stats.height = settings_.height;
    stats.samples_per_pixel = settings_.samples_per_pixel;
    stats.cone_antialiasing = settings_.cone_antialiasing;
    stats.threads = threads;
    stats.seconds = seconds;
    stats.prepare_seconds = prepare_seconds_;
    stats.methods = prepared_.method_counts();
    stats.partitions = prepared_.partition_summary();
    stats.blobs = prepared_.blob_summary();
    stats.warnings = scene_.warnings;
    stats.warnings.insert(stats.warnings.end(), prepared_.warnings().begin(), prepared_.warnings().end());
    return stats;
}

}  // namespace zeroset
