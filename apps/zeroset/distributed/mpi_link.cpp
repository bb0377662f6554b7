// MPI calls behind mpi_link.hpp; every failure of MPI itself ends the job
// (MPI_ERRORS_ARE_FATAL, Open MPI's default), so these return no status.
#include "mpi_link.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace zeroset::cli::mpi {

namespace {

/// How long a waiting loop sleeps between polls: short against a tile's
/// tracing (milliseconds), long enough to leave the core to the render threads.
constexpr auto poll_pause = std::chrono::microseconds(100);

/// The most bytes one MPI call carries (its counts are ints).
constexpr std::size_t max_chunk = std::size_t{1} << 30;

}  // namespace

Session::Session() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) {
        MPI_Finalize();
        throw std::runtime_error("the MPI library does not allow threads beside the one that calls it");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() { MPI_Finalize(); }

void send(int to, Tag tag, std::string_view bytes) {
    if (bytes.size() > max_chunk) throw std::runtime_error("a message between ranks is larger than 1 GiB");
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, static_cast<int>(tag), MPI_COMM_WORLD);
}

std::optional<Message> poll(int from) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(from < 0 ? MPI_ANY_SOURCE : from, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    Message m;
    m.from = status.MPI_SOURCE;
    m.tag = static_cast<Tag>(status.MPI_TAG);
    m.bytes.resize(static_cast<std::size_t>(count));
    MPI_Recv(m.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return m;
}

Message receive(int from) {
    while (true) {
        if (auto m = poll(from)) return std::move(*m);
        std::this_thread::sleep_for(poll_pause);
    }
}

std::string broadcast(std::string bytes, int rank) {
    unsigned long long size = bytes.size();
    MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    if (rank != 0) bytes.resize(static_cast<std::size_t>(size));
    for (std::size_t at = 0; at < bytes.size(); at += max_chunk) {
        const std::size_t n = std::min(max_chunk, bytes.size() - at);
        MPI_Bcast(bytes.data() + at, static_cast<int>(n), MPI_BYTE, 0, MPI_COMM_WORLD);
    }
    return bytes;
}

}  // namespace zeroset::cli::mpi
