// One rank's render threads in a distributed render. Rank 0 hands out work
// items (a tile of a frame); the rank's communicating thread pushes them
// here and takes the traced tiles back to send. Frames are loaded and
// prepared when opened, once per rank, and freed when closed; each thread
// keeps its tracer for the frame it is on.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "../render_job.hpp"
#include "zeroset/render/frame_render.hpp"
#include "zeroset/render/tile_result.hpp"

namespace zeroset::cli {

/// A tile of a frame: what rank 0 hands out.
struct WorkItem {
    std::int32_t frame = 0;
    std::uint32_t tile = 0;
};

/// A frame's scene and its prepared render, kept together (the render refers to the scene).
struct OpenFrame {
    Scene scene;
    std::unique_ptr<FrameRender> render;
};

class RankPool {
public:
    /// Starts `threads` render threads (all cores when 0), idle until work comes.
    RankPool(const RenderJob& job, int threads);
    /// Stops the threads, dropping work not yet started.
    ~RankPool();
    RankPool(const RankPool&) = delete;
    RankPool& operator=(const RankPool&) = delete;

    [[nodiscard]] int threads() const { return thread_count_; }

    /// Loads and prepares the frame unless it is open (SceneError, RenderError).
    const OpenFrame& open_frame(std::int32_t frame);
    /// Frees the frame; its tiles must all be done.
    void close_frame(std::int32_t frame);
    /// Frees the open frames before `frame` that have no tile waiting or being traced.
    void close_idle_frames_before(std::int32_t frame);

    /// Queues a tile of an open frame.
    void push(const WorkItem& item);
    /// A traced tile, waiting up to `wait` for one.
    std::optional<TileResult> take_finished(std::chrono::microseconds wait);
    /// Why a tile could not be traced — a frame's failure (a NaN, its
    /// budget spent…), open or since closed, or an exception in a thread —
    /// once there is a reason.
    [[nodiscard]] std::optional<std::string> failure() const;

private:
    struct Frame {
        std::shared_ptr<OpenFrame> open;
        int pending = 0;  // tiles queued or being traced
    };
    void run();
    std::map<std::int32_t, Frame>::iterator close(std::map<std::int32_t, Frame>::iterator frame);  // mutex_ held
    TileResult trace(const WorkItem& item, OpenFrame& frame, FrameRender::Worker& worker) const;

    const RenderJob& job_;
    mutable std::mutex mutex_;
    std::condition_variable work_ready_;
    std::condition_variable tile_ready_;
    std::map<std::int32_t, Frame> frames_;
    std::deque<WorkItem> queue_;
    std::deque<TileResult> finished_;
    std::optional<std::string> kept_failure_;  // of a thread, or of a frame since closed
    bool stopping_ = false;
    int thread_count_ = 1;
    std::vector<std::jthread> threads_;
};

}  // namespace zeroset::cli
