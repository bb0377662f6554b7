// SIGINT, SIGTERM and SIGHUP end the program at once, with a message, and
// without leaving the temporary file of an image being written behind
// (io/pending_files.hpp). Rendering keeps no other state worth saving: the
// image is written only when it is complete.
#pragma once

namespace zeroset::cli {

/// Installs the handlers; call once, first thing in main().
void handle_interrupts();

/// In a distributed render: rank 0 explains that mpirun ended the job
/// (another rank failed); the other ranks stay silent, leaving it to rank 0.
void explain_termination_as_rank(int rank);

}  // namespace zeroset::cli
