// Whole-file reads with readable failure reasons; each question is answered
// from a replayed snapshot when the thread has one, and recorded when it
// records (file_snapshot.hpp).
#include "zeroset/scene/file_text.hpp"

#include "zeroset/scene/file_snapshot.hpp"

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>

namespace zeroset {

namespace {

/// What a file that is not a regular one is, for messages.
std::string kind_of(std::filesystem::file_type type) {
    switch (type) {
        case std::filesystem::file_type::directory: return "it is a directory";
        case std::filesystem::file_type::fifo: return "it is a FIFO (a named pipe), not a regular file";
        case std::filesystem::file_type::socket: return "it is a socket, not a regular file";
        case std::filesystem::file_type::block:
        case std::filesystem::file_type::character: return "it is a device, not a regular file";
        default: return "it is not a regular file";
    }
}

std::string read_from_disk(const std::filesystem::path& path) {
    std::error_code status_error;
    const auto status = std::filesystem::status(path, status_error);
    if (status.type() == std::filesystem::file_type::not_found)
        throw FileReadError("no such file or directory");
    // Only regular files: a directory "opens" on POSIX, a FIFO blocks, /dev/zero never ends.
    if (!status_error && status.type() != std::filesystem::file_type::regular) throw FileReadError(kind_of(status.type()));
    const auto too_large = [] {
        return FileReadError("it is larger than " + std::to_string(max_text_file_bytes >> 20) +
                             " MiB, the most a scene, include, model or ray list may be");
    };
    std::error_code size_error;
    if (const auto size = std::filesystem::file_size(path, size_error); !size_error && size > max_text_file_bytes)
        throw too_large();
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileReadError(errno != 0 ? std::generic_category().message(errno) : "it cannot be opened");
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {  // and never more than the limit, should it grow
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_text_file_bytes) throw too_large();
    }
    if (in.bad()) throw FileReadError("it cannot be read");
    return text;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path) {
    if (const FileSnapshot* replay = detail::replay_snapshot()) {
        const auto it = replay->texts.find(path.string());
        if (it == replay->texts.end()) throw FileReadError("it is not among the files rank 0 sent");
        return it->second;
    }
    std::string text = read_from_disk(path);
    if (FileSnapshot* record = detail::recording_snapshot()) record->texts[path.string()] = text;
    return text;
}

bool regular_file_exists(const std::filesystem::path& path) {
    if (const FileSnapshot* replay = detail::replay_snapshot()) {
        const auto it = replay->regular.find(path.string());
        return it != replay->regular.end() && it->second;
    }
    std::error_code error;
    const bool regular = std::filesystem::is_regular_file(path, error);
    if (FileSnapshot* record = detail::recording_snapshot()) record->regular[path.string()] = regular;
    return regular;
}

std::filesystem::path canonical_path(const std::filesystem::path& path) {
    if (const FileSnapshot* replay = detail::replay_snapshot()) {
        const auto it = replay->canonical.find(path.string());
        return it != replay->canonical.end() ? std::filesystem::path(it->second) : path;
    }
    std::error_code error;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    if (error) canonical = path;
    if (FileSnapshot* record = detail::recording_snapshot()) record->canonical[path.string()] = canonical.string();
    return canonical;
}

}  // namespace zeroset
