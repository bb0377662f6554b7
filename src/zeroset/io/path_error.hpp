// PathError: a file operation failed; the message is "<path>: <reason>".
// Reading and writing images, and atomic file replacement, each throw their
// own subclass so callers can tell them apart.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace zeroset {

class PathError : public std::runtime_error {
public:
    PathError(const std::filesystem::path& path, const std::string& reason)
        : std::runtime_error(path.string() + ": " + reason), path_(path), reason_(reason) {}
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] const std::string& reason() const { return reason_; }

private:
    std::filesystem::path path_;
    std::string reason_;
};

}  // namespace zeroset
