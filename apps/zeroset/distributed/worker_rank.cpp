// The worker's loop: send traced tiles, take new ones, stop when told. A
// failure here (a NaN, the budget, an exception) is sent to rank 0, which
// reports it and aborts every rank.
#include "worker_rank.hpp"

#include <exception>

#include "mpi_link.hpp"
#include "rank_pool.hpp"
#include "zeroset/math/byte_buffer.hpp"

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

int run_worker_rank(const RenderJob& job, const FileSnapshot& files) {
    const FileReplay replay(files);
    std::optional<RankPool> pool;
    try {
        pool.emplace(job, job.threads());
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    ByteWriter ready;
    ready.put<std::int32_t>(pool->threads());
    mpi::send(0, mpi::Tag::Ready, ready.take());

    int in_flight = 0;
    bool done = false;
    std::int32_t newest_frame = 0;
    while (!(done && in_flight == 0)) {
        if (auto why = pool->failure()) return fail(*why);
        while (auto tile = pool->take_finished(tile_wait)) {
            --in_flight;
            mpi::send(0, mpi::Tag::Tile, tile->pack());
            pool->close_idle_frames_before(newest_frame);
            if (auto why = pool->failure()) return fail(*why);
        }
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
        try {
            ByteReader in(message->bytes, "the work rank 0 sent");
            for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
                const auto item = in.get<WorkItem>();
                pool->open_frame(item.frame);
                if (item.frame > newest_frame) pool->close_idle_frames_before(newest_frame = item.frame);
                pool->push(item);
                ++in_flight;
            }
        } catch (const std::exception& e) {
            return fail(e.what());
        }
    }
    return 0;
}

}  // namespace zeroset::cli
