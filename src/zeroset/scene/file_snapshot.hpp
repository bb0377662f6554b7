// The files a scene load reads, kept so that the load can be repeated
// elsewhere without them: rank 0 of a distributed render records what
// loading the scene read and asked (texts, canonical names, which include
// candidates exist) and sends it; the other ranks replay it, so they need no
// shared file system. Recording and replay hook read_text_file and its
// siblings (file_text.hpp) for the thread that holds them.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace zeroset {

struct FileSnapshot {
    std::map<std::string, std::string> texts;      // read_text_file: path → whole text
    std::map<std::string, std::string> canonical;  // canonical_path: path → its answer
    std::map<std::string, bool> regular;           // regular_file_exists: path → its answer

    /// A flat byte string of the above, and back; unpack throws
    /// std::runtime_error on bytes pack did not make.
    [[nodiscard]] std::string pack() const;
    static FileSnapshot unpack(std::string_view bytes);
};

/// While one lives, every file question this thread asks is answered from
/// the disk as usual and added to `into`.
class FileRecording {
public:
    explicit FileRecording(FileSnapshot& into);
    ~FileRecording();
    FileRecording(const FileRecording&) = delete;
    FileRecording& operator=(const FileRecording&) = delete;
};

/// While one lives, every file question this thread asks is answered from
/// `from` alone: a file it lacks cannot be read.
class FileReplay {
public:
    explicit FileReplay(const FileSnapshot& from);
    ~FileReplay();
    FileReplay(const FileReplay&) = delete;
    FileReplay& operator=(const FileReplay&) = delete;
};

namespace detail {
/// The thread's recording and replay, null when none (file_text.cpp asks).
FileSnapshot* recording_snapshot();
const FileSnapshot* replay_snapshot();
}  // namespace detail

}  // namespace zeroset
