// The local scheduler: a frame's tiles handed out to std::threads, first
// come first served; validation of settings shared by every renderer.
#include "zeroset/render/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "zeroset/render/frame_render.hpp"

namespace zeroset {

namespace {

constexpr int max_samples_per_pixel = 1024;

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
    const auto start = std::chrono::steady_clock::now();
    FrameRender frame(scene, settings);
    const std::vector<TileRect>& tiles = frame.tiles();
    const int thread_count = settings.threads > 0
                                 ? settings.threads
                                 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

    RenderResult result{Image(settings.width, settings.height), {}};
    if (settings.layers) result.image.add_layers();
    std::vector<TileWork> work(static_cast<std::size_t>(thread_count));
    std::atomic<std::size_t> next_tile{0};
    std::mutex progress_mutex;
    int tiles_done = 0;

    const auto thread = [&](TileWork& mine) {
        FrameRender::Worker worker(frame, thread_count);
        for (std::size_t i = next_tile++; i < tiles.size(); i = next_tile++) {
            const TileWork tile = frame.render_tile(i, worker, result.image);
            mine += tile;
            if (settings.on_progress || settings.on_tile) {
                std::lock_guard lock(progress_mutex);
                if (settings.on_tile) settings.on_tile(tiles[i], tile);
                if (settings.on_progress) settings.on_progress(++tiles_done, static_cast<int>(tiles.size()));
            }
        }
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < thread_count; ++t) pool.emplace_back(thread, std::ref(work[static_cast<std::size_t>(t)]));
        thread(work[0]);
    }
    TileWork all;
    for (const TileWork& w : work) all += w;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.stats = frame.finish(all, thread_count, seconds);
    return result;
}

}  // namespace zeroset
