// Thread-local hooks for recording and replaying file reads, and the byte
// form a snapshot travels in.
#include "zeroset/scene/file_snapshot.hpp"

#include <cstdint>

#include "zeroset/math/byte_buffer.hpp"

namespace zeroset {

namespace {

thread_local FileSnapshot* recording = nullptr;
thread_local const FileSnapshot* replaying = nullptr;

}  // namespace

std::string FileSnapshot::pack() const {
    ByteWriter out;
    out.put<std::uint64_t>(texts.size());
    for (const auto& [path, text] : texts) out.put_text(path), out.put_text(text);
    out.put<std::uint64_t>(canonical.size());
    for (const auto& [path, answer] : canonical) out.put_text(path), out.put_text(answer);
    out.put<std::uint64_t>(regular.size());
    for (const auto& [path, answer] : regular) out.put_text(path), out.put<std::uint8_t>(answer ? 1 : 0);
    return out.take();
}

FileSnapshot FileSnapshot::unpack(std::string_view bytes) {
    ByteReader in(bytes, "the scene files sent by rank 0");
    FileSnapshot s;
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
        std::string path = in.get_text();
        s.texts[std::move(path)] = in.get_text();
    }
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
        std::string path = in.get_text();
        s.canonical[std::move(path)] = in.get_text();
    }
    for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
        std::string path = in.get_text();
        s.regular[std::move(path)] = in.get<std::uint8_t>() != 0;
    }
    in.expect_end();
    return s;
}

FileRecording::FileRecording(FileSnapshot& into) { recording = &into; }
FileRecording::~FileRecording() { recording = nullptr; }
FileReplay::FileReplay(const FileSnapshot& from) { replaying = &from; }
FileReplay::~FileReplay() { replaying = nullptr; }

namespace detail {
FileSnapshot* recording_snapshot() { return recording; }
const FileSnapshot* replay_snapshot() { return replaying; }
}  // namespace detail

}  // namespace zeroset
