// The coordinator's loop: hand out, gather, write; and on any failure, stop
// every rank before reporting it, so that no rank is left waiting.
#include "coordinator.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>

#include "../progress_bar.hpp"
#include "../tile_log.hpp"
#include "mpi_link.hpp"
#include "rank_pool.hpp"
#include "zeroset/math/byte_buffer.hpp"

namespace zeroset::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// Tiles a rank keeps in flight per thread: one being traced, one waiting,
/// so that it never idles for a round trip to rank 0.
constexpr int tiles_in_flight_per_thread = 2;

/// How long the loop waits for one of its own tiles before looking for messages.
constexpr auto tile_wait = std::chrono::microseconds(200);

struct RankState {
    int threads = 1;
    int in_flight = 0;
    bool done_sent = false;  // told there is no more work: it has stopped
    std::uint64_t tiles = 0;
    double thread_seconds = 0.0;
    std::uint64_t evaluations = 0;
};

struct FrameState {
    Image image;
    std::size_t tiles_left = 0;
    TileWork work;
    Clock::time_point start;
};

class Coordinator {
public:
    Coordinator(const RenderJob& job, int ranks, const std::vector<FrameSize>& frame_sizes)
        : job_(job), frame_sizes_(frame_sizes), ranks_(static_cast<std::size_t>(ranks)) {
        for (std::size_t frame = 0; frame < frame_sizes.size(); ++frame) total_tiles_ += tiles_in(frame);
    }

    int run() {
        try {
            gather();
        } catch (...) {
            bar_.finish();
            abort_workers();
            throw;
        }
        bar_.finish();
        if (job_.tile_log()) log_.write(*job_.tile_log());
        if (!job_.quiet()) report_ranks();
        return 0;
    }

private:
    void gather() {
        pool_.emplace(job_, job_.threads());
        ranks_[0].threads = pool_->threads();
        for (std::size_t rank = 1; rank < ranks_.size(); ++rank) {
            const mpi::Message ready = mpi::receive(static_cast<int>(rank));
            if (ready.tag == mpi::Tag::Error) throw RenderError("rank " + std::to_string(rank) + ": " + ready.bytes);
            ranks_[rank].threads = ByteReader(ready.bytes, "a rank's first message").get<std::int32_t>();
        }
        for (std::size_t rank = 1; rank < ranks_.size(); ++rank) hand_out(rank);
        hand_out(0);
        while (frames_written_ < frame_sizes_.size()) {
            if (auto why = pool_->failure()) throw RenderError(*why);
            // One of its own tiles at most, then every message: rank 0's
            // cheap tiles must not keep the other ranks waiting.
            if (auto tile = pool_->take_finished(tile_wait)) {
                if (auto why = pool_->failure()) throw RenderError(*why);  // the tile may have been stopped
                accept(0, std::move(*tile));
                hand_out(0);
            }
            while (auto message = mpi::poll()) {
                const auto rank = static_cast<std::size_t>(message->from);
                if (message->tag == mpi::Tag::Error)
                    throw RenderError("rank " + std::to_string(rank) + ": " + message->bytes);
                if (message->tag != mpi::Tag::Tile) continue;
                accept(rank, TileResult::unpack(message->bytes));
                hand_out(rank);
            }
        }
    }

    /// Fills the rank's tiles in flight from the queue; tells a remote rank
    /// that has none left and nothing in flight that the job is done.
    void hand_out(std::size_t rank) {
        RankState& state = ranks_[rank];
        std::vector<WorkItem> items;
        while (state.in_flight < tiles_in_flight_per_thread * state.threads && next_frame_ < frame_sizes_.size()) {
            items.push_back({static_cast<std::int32_t>(next_frame_), static_cast<std::uint32_t>(next_tile_)});
            ++state.in_flight;
            if (++next_tile_ == tiles_in(next_frame_)) ++next_frame_, next_tile_ = 0;
        }
        if (rank == 0) {
            for (const WorkItem& item : items) open(item.frame), pool_->push(item);
        } else if (!items.empty()) {
            ByteWriter out;
            out.put<std::uint64_t>(items.size());
            for (const WorkItem& item : items) out.put(item);
            mpi::send(static_cast<int>(rank), mpi::Tag::Work, out.take());
            for (const WorkItem& item : items) open(item.frame);
        } else if (state.in_flight == 0 && !state.done_sent && next_frame_ == frame_sizes_.size()) {
            mpi::send(static_cast<int>(rank), mpi::Tag::Done, {});
            state.done_sent = true;
        }
    }

    /// Rank 0 prepares every frame as its first tile is handed out: its
    /// render's stats and failure checks speak for the whole frame.
    void open(std::int32_t frame) {
        if (frames_.contains(frame)) return;
        const OpenFrame& opened = pool_->open_frame(frame);
        FrameState& state = frames_[frame];
        state.image = Image(opened.render->settings().width, opened.render->settings().height);
        if (opened.render->settings().layers) state.image.add_layers();
        state.tiles_left = tiles_in(static_cast<std::size_t>(frame));
        state.start = Clock::now();
    }

    void accept(std::size_t rank, TileResult tile) {
        RankState& state = ranks_[rank];
        --state.in_flight;
        ++state.tiles;
        state.thread_seconds += tile.work.seconds;
        state.evaluations += tile.work.trace.evaluations();
        const auto found = frames_.find(tile.frame);
        if (found == frames_.end() || tile.tile >= tiles_in(static_cast<std::size_t>(tile.frame)))
            throw RenderError("rank " + std::to_string(rank) + " sent a tile that was never handed out");
        FrameState& frame = found->second;
        const FrameSize& size = frame_sizes_[static_cast<std::size_t>(tile.frame)];
        const TileRect rect = tile_at(size.width, size.height, tile.tile);
        if (tile.pixels.width != rect.width() || tile.pixels.height != rect.height() ||
            tile.pixels.has_layers() != frame.image.has_layers())
            throw RenderError("rank " + std::to_string(rank) + " sent a tile of the wrong size (is it the same build?)");
        place_tile(tile.pixels, rect, frame.image);
        frame.work += tile.work;
        if (job_.tile_log()) log_.add(static_cast<std::size_t>(tile.frame), static_cast<int>(rank), rect, tile.work);
        FrameRender& render = *pool_->open_frame(tile.frame).render;
        if (frame.work.trace.evaluations() > render.budget()) {
            render.stop_over_budget();
            throw RenderError(*render.failure());
        }
        if (!job_.quiet() && bar_.enabled()) bar_.update(static_cast<int>(++tiles_done_), static_cast<int>(total_tiles_));
        if (--frame.tiles_left == 0) write_frame(tile.frame);
    }

    void write_frame(std::int32_t number) {
        FrameState& frame = frames_.at(number);
        const FrameRender& render = *pool_->open_frame(number).render;
        int threads = 0;
        for (const RankState& rank : ranks_) threads += rank.threads;
        const RenderStats stats = render.finish(
            frame.work, threads, std::chrono::duration<double>(Clock::now() - frame.start).count());
        bar_.finish();
        job_.write_frame(static_cast<std::size_t>(number), frame.image, stats);
        frames_.erase(number);
        pool_->close_frame(number);
        ++frames_written_;
    }

    /// Per rank: tiles, tracing time and evaluations; and the imbalance.
    void report_ranks() const {
        double busiest = 0.0, sum = 0.0;
        for (std::size_t rank = 0; rank < ranks_.size(); ++rank) {
            const RankState& r = ranks_[rank];
            const double seconds = r.thread_seconds / r.threads;
            busiest = std::max(busiest, seconds);
            sum += seconds;
            std::fprintf(stderr, "zeroset: rank %zu: %llu tiles, %.3f s tracing on %d thread%s, %.4gM evaluations\n", rank,
                         static_cast<unsigned long long>(r.tiles), seconds, r.threads, r.threads == 1 ? "" : "s",
                         static_cast<double>(r.evaluations) / 1e6);
        }
        const double mean = sum / static_cast<double>(ranks_.size());
        std::fprintf(stderr,
                     "zeroset: %zu ranks, load imbalance %.3f (the busiest rank's tracing time over the mean)\n",
                     ranks_.size(), mean > 0.0 ? busiest / mean : 1.0);
    }

    /// Tells every rank still running to stop, and waits until each has:
    /// then no rank is left waiting for rank 0, and MPI can be finalised.
    void abort_workers() noexcept {
        std::size_t running = 0;
        for (std::size_t rank = 1; rank < ranks_.size(); ++rank) {
            if (ranks_[rank].done_sent) continue;
            mpi::send(static_cast<int>(rank), mpi::Tag::Abort, {});
            ++running;
        }
        while (running > 0)
            if (mpi::receive().tag == mpi::Tag::Bye) --running;
    }

    const RenderJob& job_;
    [[nodiscard]] std::size_t tiles_in(std::size_t frame) const {
        return tile_count(frame_sizes_[frame].width, frame_sizes_[frame].height);
    }

    const std::vector<FrameSize>& frame_sizes_;
    std::vector<RankState> ranks_;
    std::optional<RankPool> pool_;  // made in gather(), so that a failure to make it stops the other ranks too
    std::map<std::int32_t, FrameState> frames_;
    std::size_t next_frame_ = 0, next_tile_ = 0;
    std::size_t total_tiles_ = 0, tiles_done_ = 0;
    std::size_t frames_written_ = 0;
    ProgressBar bar_;
    TileLog log_;
};

}  // namespace

int run_coordinator(const RenderJob& job, int ranks, const std::vector<FrameSize>& frame_sizes) {
    return Coordinator(job, ranks, frame_sizes).run();
}

}  // namespace zeroset::cli
