// The few MPI calls a distributed render makes, on MPI_COMM_WORLD: start and
// stop, whole byte strings sent and received under a tag, and polling for a
// message without blocking (Open MPI's blocking receive spins a core, which
// on a busy node would be taken from the render threads). Only the thread
// that started MPI calls these (MPI_THREAD_FUNNELED).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace zeroset::cli::mpi {

/// What a message is, by its MPI tag.
enum class Tag : int {
    Ready = 1,  // rank → 0: started, with its thread count
    Work,       // 0 → rank: tiles to trace
    Done,       // 0 → rank: no more tiles; finish and stop
    Abort,      // 0 → rank: the job failed; stop now
    Tile,       // rank → 0: a traced tile (TileResult)
    Error,      // rank → 0: why this rank failed
    Bye,        // rank → 0: stopped after an Abort
};

/// MPI started for this process (MPI_Init_thread, funneled) and finalised
/// when destroyed.
class Session {
public:
    Session();
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] int size() const { return size_; }

private:
    int rank_ = 0;
    int size_ = 1;
};

struct Message {
    int from = 0;
    Tag tag = Tag::Ready;
    std::string bytes;
};

void send(int to, Tag tag, std::string_view bytes);
/// The next message from `from` (any rank when -1), if one has arrived.
std::optional<Message> poll(int from = -1);
/// Waits for the next message from `from` (any rank when -1), polling with
/// short sleeps rather than spinning.
Message receive(int from = -1);
/// Rank 0's bytes on every rank (any size).
std::string broadcast(std::string bytes, int rank);

}  // namespace zeroset::cli::mpi
