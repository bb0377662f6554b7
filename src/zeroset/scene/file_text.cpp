// Whole-file reads with readable failure reasons.
#include "zeroset/scene/file_text.hpp"

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>

namespace zeroset {

std::string read_text_file(const std::filesystem::path& path) {
    std::error_code status_error;
    const auto status = std::filesystem::status(path, status_error);
    if (status.type() == std::filesystem::file_type::not_found)
        throw FileReadError("no such file or directory");
    // Opening a directory succeeds on POSIX; reading it fails.
    if (status.type() == std::filesystem::file_type::directory) throw FileReadError("it is a directory");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileReadError(errno != 0 ? std::generic_category().message(errno) : "it cannot be opened");
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw FileReadError("it cannot be read");
    return text;
}

std::filesystem::path canonical_path(const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    return error ? path : canonical;
}

}  // namespace zeroset
