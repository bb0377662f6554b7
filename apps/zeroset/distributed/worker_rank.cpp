// The worker's loop: send traced tiles, take new ones, stop when told. A
// failure here (a NaN, the budget, an exception) is sent to rank 0, which
// reports it and aborts every rank.
#include "worker_rank.hpp"

#include <exception>

#include "mpi_link.hpp"
#include "rank_pool.hpp"
#include "zeroset/math/byte_buffer.hpp"
#include "zeroset/scene/file_snapshot.hpp"

namespace zeroset::cli {

namespace {

/// How long the loop waits for a traced tile before looking for messages.
constexpr auto tile_wait = std::chrono::microseconds(200);

/// After a failure: rank 0 answers with Abort; anything else still in flight
/// is dropped. The rank then ends with status 0: rank 0 reports the failure
/// and ends with 1, which is the job's status — a worker ending first with 1
/// would have mpirun kill rank 0 before it could say why.
int wait_for_abort() {
    while (mpi::receive(0).tag != mpi::Tag::Abort) {
    }
    mpi::send(0, mpi::Tag::Bye, {});
    return 0;
}

int fail(const std::string& why) {
    mpi::send(0, mpi::Tag::Error, why);
    return wait_for_abort();
}

}  // namespace

namespace {

/// The loop itself; any exception is the caller's to report.
int serve(const RenderJob& job) {
    std::optional<RankPool> pool(std::in_place, job, job.threads());
    ByteWriter ready;
    ready.put<std::int32_t>(pool->threads());
    mpi::send(0, mpi::Tag::Ready, ready.take());

    int in_flight = 0;
    bool done = false;
    std::int32_t newest_frame = 0;
    while (!(done && in_flight == 0)) {
        while (auto tile = pool->take_finished(tile_wait)) {
            // Checked after the tile is out of the pool and before it is
            // sent: a tile stopped by a failure, or the failure of a frame
            // about to be freed, is reported instead of sent.
            if (auto why = pool->failure()) return fail(*why);
            --in_flight;
            mpi::send(0, mpi::Tag::Tile, tile->pack());
            pool->close_idle_frames_before(newest_frame);
        }
        if (auto why = pool->failure()) return fail(*why);
        const auto message = mpi::poll(0);
        if (!message) continue;
        if (message->tag == mpi::Tag::Abort) {
            pool.reset();
            mpi::send(0, mpi::Tag::Bye, {});
            return 0;  // rank 0 reports why (wait_for_abort)
        }
        if (message->tag == mpi::Tag::Done) {
            done = true;
            continue;
        }
        ByteReader in(message->bytes, "the work rank 0 sent");
        for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
            const auto item = in.get<WorkItem>();
            pool->open_frame(item.frame);
            if (item.frame > newest_frame) pool->close_idle_frames_before(newest_frame = item.frame);
            pool->push(item);
            ++in_flight;
        }
    }
    return 0;
}

}  // namespace

int run_worker_rank(const RenderJob& job, std::string_view files) {
    try {
        const FileSnapshot snapshot = FileSnapshot::unpack(files);
        const FileReplay replay(snapshot);
        return serve(job);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}

}  // namespace zeroset::cli
