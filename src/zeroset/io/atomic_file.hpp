// Atomic file replacement: output goes to a uniquely named temporary file in
// the target's directory and is renamed onto the target only once it is
// completely written and synced. A failed or interrupted write therefore
// never leaves a half-written target, and the temporary file is removed —
// by a signal handler too (io/pending_files.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "zeroset/io/path_error.hpp"

namespace zeroset {

/// A file could not be written; the message is "<path>: <reason>".
class FileWriteError : public PathError {
public:
    using PathError::PathError;
};

/// One atomic write of `target`: construct (creates the temporary file),
/// write(), then commit(). Destroying an uncommitted AtomicFile, or any
/// failure in write()/commit(), removes the temporary file; the target is
/// then untouched. Every failure throws FileWriteError naming the target.
class AtomicFile {
public:
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(std::span<const std::uint8_t> bytes);
    /// Flushes to disk, closes and renames onto the target. Call once.
    void commit();

    [[nodiscard]] const std::filesystem::path& target() const { return target_; }
    [[nodiscard]] const std::filesystem::path& temp_path() const { return temp_; }

private:
    [[noreturn]] void fail(const std::string& what, int error_number);
    void discard() noexcept;

    std::filesystem::path target_;
    std::filesystem::path temp_;
    int fd_ = -1;
    int pending_slot_ = -1;  // in io/pending_files.hpp, while the temporary file exists
    bool committed_ = false;
};

/// Writes `bytes` to `target` atomically (AtomicFile in one call).
void write_file_atomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);

}  // namespace zeroset
