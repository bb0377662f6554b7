// The temporary files being written right now, for a signal handler to
// remove: when SIGINT or SIGTERM ends the program during an atomic write
// (io/atomic_file.hpp), no hidden ".NAME.tmp-PID-N" file may stay behind.
// Registering and removing are lock-free, and remove_pending_files() only
// calls unlink(), so it is async-signal-safe.
#pragma once

#include <filesystem>

namespace zeroset {

/// Notes a temporary file about to be created and returns its slot, or -1
/// when all slots are in use (then a signal simply leaves that file behind).
int register_pending_file(const std::filesystem::path& path);
/// Forgets the slot (the file was renamed or removed).
void unregister_pending_file(int slot);
/// Removes every file still registered. Async-signal-safe.
void remove_pending_files() noexcept;

}  // namespace zeroset
