// One frame rendered tile by tile: the scene prepared once, and the "render
// this tile" call that both schedulers drive — the thread pool of render()
// (renderer.hpp) and the ranks of a distributed render (cluster/). A pixel's
// samples depend on the pixel alone (pixel_samples.hpp), so the image is the
// same bit for bit however its tiles are spread over threads or machines.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/render/camera_rays.hpp"
#include "zeroset/render/cone_tracer.hpp"
#include "zeroset/render/image.hpp"
#include "zeroset/render/prepared_scene.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/render/render_stats.hpp"
#include "zeroset/render/scene_distance.hpp"
#include "zeroset/render/scene_tracer.hpp"
#include "zeroset/render/tile_work.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

class FrameRender {
public:
    /// Checks the settings and the camera and prepares the scene (tapes,
    /// methods, BVHs, octrees); throws RenderError. The scene must outlive this.
    FrameRender(const Scene& scene, const RenderSettings& settings);
    ~FrameRender();
    FrameRender(const FrameRender&) = delete;
    FrameRender& operator=(const FrameRender&) = delete;

    [[nodiscard]] const std::vector<TileRect>& tiles() const { return tiles_; }
    [[nodiscard]] const RenderSettings& settings() const { return settings_; }
    [[nodiscard]] double prepare_seconds() const { return prepare_seconds_; }

    /// One thread's tracer and counters; make one per thread, and use it
    /// from that thread only.
    class Worker {
    public:
        Worker(FrameRender& frame, int threads_sharing_the_budget);

    private:
        friend class FrameRender;
        SceneTracer tracer_;
        std::optional<ConeTracer> cone_;
        std::uint64_t threads_ = 1;                 // the budget's left part is shared by this many
        std::uint64_t evaluations_reported_ = 0;  // of the tracer's, added to the frame's total
    };

    /// Traces tile `index` into `into`, whose pixel (0, 0) is the image's
    /// (origin_x, origin_y): the whole image with origin (0, 0), or an image
    /// of the tile's size with the tile's corner as origin. Returns what it
    /// cost. Once the render has failed (failure()), returns at once.
    TileWork render_tile(std::size_t index, Worker& worker, Image& into, int origin_x = 0, int origin_y = 0);

    /// Why the render stopped early — a NaN, the evaluation budget spent, a
    /// pixel with no finite colour — or nothing while it has not.
    [[nodiscard]] std::optional<std::string> failure() const;
    /// True once failure() has something to say: the rest is not worth tracing.
    [[nodiscard]] bool stopped() const { return stop_.load(std::memory_order_relaxed); }

    /// The render's stats from the work of all its tiles (seconds measured by
    /// the caller); throws RenderError with failure() if there is one.
    [[nodiscard]] RenderStats finish(const TileWork& all_tiles, int threads, double seconds) const;

    /// Stops the render without a failure: the tiles being traced end at
    /// their next pixel (a job abandoned for another reason).
    void cancel() { stop_ = true; }

    /// Stops the render as over budget: a scheduler that counts the
    /// evaluations of many workers (ranks) calls it when their sum passes
    /// budget().
    void stop_over_budget();
    [[nodiscard]] std::uint64_t budget() const { return budget_; }

private:
    friend class Worker;
    /// Adds the worker's evaluations to the frame's total: after a pixel
    /// once they pass report_interval (or a NaN or the worker's allowance
    /// calls for it), and at a tile's end always (`flush`).
    void report(Worker& worker, bool flush);
    static constexpr std::uint64_t report_interval = 4096;
    void allow(Worker& worker, std::uint64_t total) const;
    void record_nan(const TraceScratch::NanRecord& nan);
    void record_non_finite(int px, int py);
    /// A tile, or its rows left, proven to see no surface (Primitive::misses_tile): the background, with no ray made.
    void fill_with_background(const TileRect& tile, Image& into, int origin_x, int origin_y, TileWork& work);

    std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
    const Scene& scene_;
    RenderSettings settings_;
    PreparedScene prepared_;
    CameraRays camera_;
    // Whether camera rays come with their tiles: asked for, and some leaf is
    // partitioned (it culls them) or some object is a blob (it lists its
    // components by them); for the others a tile would only cost.
    bool cull_camera_tiles_ = false;
    std::optional<SceneDistance> distance_;
    std::vector<TileRect> tiles_;
    double prepare_seconds_ = 0.0;

    // Shared by the workers, to stop early: evaluations spent against the
    // budget, and the first reason met to stop.
    std::uint64_t budget_ = 0;
    std::atomic<std::uint64_t> spent_{0};
    std::atomic<bool> over_budget_{false};
    std::atomic<bool> stop_{false};
    mutable std::mutex failure_mutex_;
    std::optional<std::string> nan_failure_;
    std::optional<std::string> non_finite_failure_;
};

}  // namespace zeroset
