// The rank's render threads: a queue of tiles in, a queue of traced tiles out.
#include "rank_pool.hpp"

#include <exception>

namespace zeroset::cli {

RankPool::RankPool(const RenderJob& job, int threads) : job_(job) {
    thread_count_ = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (int i = 0; i < thread_count_; ++i) threads_.emplace_back([this] { run(); });
}

RankPool::~RankPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        queue_.clear();
        for (auto& [number, frame] : frames_) frame.open->render->cancel();
    }
    work_ready_.notify_all();
    threads_.clear();  // joins
}

const OpenFrame& RankPool::open_frame(std::int32_t frame) {
    {
        std::lock_guard lock(mutex_);
        if (const auto it = frames_.find(frame); it != frames_.end()) return *it->second.open;
    }
    auto open = std::make_shared<OpenFrame>();
    open->scene = job_.load_frame(static_cast<std::size_t>(frame), true);
    RenderSettings settings = job_.settings_for(open->scene);
    settings.threads = threads();
    open->render = std::make_unique<FrameRender>(open->scene, settings);
    std::lock_guard lock(mutex_);
    return *(frames_[frame].open = std::move(open));
}

void RankPool::close_frame(std::int32_t frame) {
    std::lock_guard lock(mutex_);
    if (const auto it = frames_.find(frame); it != frames_.end()) close(it);
}

void RankPool::close_idle_frames_before(std::int32_t frame) {
    std::lock_guard lock(mutex_);
    for (auto it = frames_.begin(); it != frames_.end() && it->first < frame;)
        it = it->second.pending == 0 ? close(it) : std::next(it);
}

/// Frees the frame, keeping its failure: a frame closed after it failed
/// must still fail the job.
std::map<std::int32_t, RankPool::Frame>::iterator RankPool::close(std::map<std::int32_t, Frame>::iterator frame) {
    if (!kept_failure_) kept_failure_ = frame->second.open->render->failure();
    return frames_.erase(frame);
}

void RankPool::push(const WorkItem& item) {
    {
        std::lock_guard lock(mutex_);
        ++frames_.at(item.frame).pending;
        queue_.push_back(item);
    }
    work_ready_.notify_one();
}

std::optional<TileResult> RankPool::take_finished(std::chrono::microseconds wait) {
    std::unique_lock lock(mutex_);
    if (!tile_ready_.wait_for(lock, wait, [this] { return !finished_.empty(); })) return std::nullopt;
    TileResult tile = std::move(finished_.front());
    finished_.pop_front();
    return tile;
}

std::optional<std::string> RankPool::failure() const {
    std::lock_guard lock(mutex_);
    if (kept_failure_) return kept_failure_;
    for (const auto& [number, frame] : frames_)
        if (auto why = frame.open->render->failure()) return why;
    return std::nullopt;
}

TileResult RankPool::trace(const WorkItem& item, OpenFrame& frame, FrameRender::Worker& worker) const {
    const TileRect& rect = frame.render->tiles().at(item.tile);
    TileResult result;
    result.frame = item.frame;
    result.tile = item.tile;
    result.pixels = Image(rect.width(), rect.height());
    if (frame.render->settings().layers) result.pixels.add_layers();
    result.work = frame.render->render_tile(item.tile, worker, result.pixels, rect.x0, rect.y0);
    return result;
}

void RankPool::run() {
    std::shared_ptr<OpenFrame> frame;  // the frame this thread's worker traces
    std::int32_t frame_number = -1;
    std::unique_ptr<FrameRender::Worker> worker;
    while (true) {
        WorkItem item;
        {
            std::unique_lock lock(mutex_);
            work_ready_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
            if (stopping_) return;
            item = queue_.front();
            queue_.pop_front();
            if (item.frame != frame_number) {
                worker.reset();
                frame = frames_.at(item.frame).open;
                frame_number = item.frame;
            }
        }
        std::optional<TileResult> traced;
        try {
            if (!worker) worker = std::make_unique<FrameRender::Worker>(*frame->render, threads());
            traced = trace(item, *frame, *worker);
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            if (!kept_failure_) kept_failure_ = e.what();
        }
        {
            std::lock_guard lock(mutex_);
            if (const auto it = frames_.find(item.frame); it != frames_.end()) --it->second.pending;
            if (traced) finished_.push_back(std::move(*traced));
        }
        tile_ready_.notify_one();
    }
}

}  // namespace zeroset::cli
