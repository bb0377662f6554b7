// Reading a scene, include or model file whole, with a reason a person can
// act on when that fails; and resolving the paths scenes write.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <cstdint>
#include <string>

namespace zeroset {

/// Why a file could not be read ("no such file or directory", "it is a directory", …).
class FileReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The most a text file the program reads may hold: scenes, includes, .vm
/// models and ray lists (the largest model shipped, prospero.vm, is 150 kB).
inline constexpr std::uintmax_t max_text_file_bytes = std::uintmax_t{256} << 20;

/// The whole content of a regular file of at most max_text_file_bytes;
/// throws FileReadError (a missing file, a directory, a FIFO or device, too
/// large, unreadable).
std::string read_text_file(const std::filesystem::path& path);

/// Whether the path names a regular file (false when it cannot be told).
bool regular_file_exists(const std::filesystem::path& path);

/// The path with symbolic links and dot segments resolved (as far as it
/// exists), naming a file the same way however it was reached; the path
/// itself if that fails.
std::filesystem::path canonical_path(const std::filesystem::path& path);

/// A path written in a scene, taken relative to the directory of the file that wrote it.
inline std::filesystem::path resolve_path(const std::filesystem::path& base_dir, const std::filesystem::path& written) {
    return (base_dir / written).lexically_normal();
}

}  // namespace zeroset
