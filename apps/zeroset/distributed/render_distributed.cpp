// The entry of a distributed render: MPI started, the scene files read by
// rank 0 and broadcast (so ranks need no shared file system), then rank 0
// coordinates and the others trace.
#include <mpi.h>

#include <cstdint>
#include <exception>

#include "../distributed_launch.hpp"
#include "../interrupts.hpp"
#include "coordinator.hpp"
#include "mpi_link.hpp"
#include "worker_rank.hpp"
#include "zeroset/math/byte_buffer.hpp"
#include "zeroset/scene/file_snapshot.hpp"

namespace zeroset::cli {

namespace {

/// Rank 0 loads every frame's scene once, recording the files it reads, and
/// checks each frame's settings; returns every frame's size.
std::vector<FrameSize> plan_frames(const RenderJob& job, FileSnapshot& files) {
    const FileRecording recording(files);
    std::vector<FrameSize> frame_sizes;
    for (std::size_t frame = 0; frame < job.frame_count(); ++frame) {
        const Scene scene = job.load_frame(frame, job.quiet() || frame > 0);
        const RenderSettings settings = job.settings_for(scene);
        frame_sizes.push_back({settings.width, settings.height});
    }
    return frame_sizes;
}

}  // namespace

int render_distributed(const RenderJob& job) {
    const mpi::Session session;
    explain_termination_as_rank(session.rank());
    if (session.rank() != 0) {
        const std::string sent = mpi::broadcast({}, session.rank());
        if (sent.empty()) return 0;  // rank 0 could not load the scene: it says why, and ends with 1
        return run_worker_rank(job, std::string_view(sent).substr(1));
    }
    FileSnapshot files;
    std::vector<FrameSize> frame_sizes;
    try {
        frame_sizes = plan_frames(job, files);
    } catch (...) {
        mpi::broadcast({}, 0);
        throw;
    }
    mpi::broadcast("+" + files.pack(), 0);
    return run_coordinator(job, session.size(), frame_sizes);
}

std::string mpi_version_line() {
    char version[MPI_MAX_LIBRARY_VERSION_STRING];
    int length = 0;
    MPI_Get_library_version(version, &length);
    std::string text(version, static_cast<std::size_t>(length));
    if (const auto end = text.find_first_of(",\n"); end != std::string::npos) text.resize(end);
    return "MPI: " + text + " (distributed rendering: mpirun -n N zeroset render …; docs/distributed.md)";
}

}  // namespace zeroset::cli
