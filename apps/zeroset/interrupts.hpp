// SIGINT, SIGTERM and SIGHUP end the program at once, with a message, and
// without leaving the temporary file of an image being written behind
// (io/pending_files.hpp). Rendering keeps no other state worth saving: the
// image is written only when it is complete.
#pragma once

namespace zeroset::cli {

/// Installs the handlers; call once, first thing in main().
void handle_interrupts();

}  // namespace zeroset::cli
