// Distributed rendering over MPI (docs/distributed.md): whether this process
// was started as one of several by mpirun, and the render that then spreads
// a job's tiles over all of them. In a build without MPI the render refuses,
// saying why, rather than have every process render the whole image.
#pragma once

#include <string>

#include "render_job.hpp"

namespace zeroset::cli {

/// True when mpirun (or another MPI launcher) started this process as one
/// of two or more.
bool distributed_launch();

/// This process's rank as the launcher gave it (0 when not launched as one
/// of several), known before MPI starts.
int launched_rank();

/// Renders the job with every rank of the MPI job; rank 0 writes the
/// images. Returns the exit status; throws on rank 0 for a failure of any
/// rank. Without MPI built in, throws UsageError.
int render_distributed(const RenderJob& job);

/// The --version line on MPI: the library built in, or that there is none.
std::string mpi_version_line();

}  // namespace zeroset::cli
