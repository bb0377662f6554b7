// read_png / read_pfm / read_exr: slurp the file, decode in memory, and put the path in
// every error message.
#include "zeroset/io/image_reader.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <system_error>
#include <vector>

#include "zeroset/io/exr.hpp"
#include "zeroset/io/pfm.hpp"
#include "zeroset/io/png.hpp"

namespace zeroset {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

std::vector<std::uint8_t> read_file(const std::filesystem::path& path) {
    errno = 0;
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw ImageReadError(path, "cannot open file: " + std::generic_category().message(errno));
    std::vector<std::uint8_t> bytes;
    std::uint8_t buffer[65536];
    for (;;) {
        errno = 0;
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
        bytes.insert(bytes.end(), buffer, buffer + n);
        if (n < sizeof buffer) break;
    }
    if (std::ferror(file.get()) != 0)
        throw ImageReadError(path, "cannot read file: " + std::generic_category().message(errno));
    return bytes;
}

template <class Decode>
Image read_with(const std::filesystem::path& path, Decode decode) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    try {
        return decode(bytes);
    } catch (const std::runtime_error& e) {
        throw ImageReadError(path, e.what());
    }
}

}  // namespace

Image read_png(const std::filesystem::path& path) {
    return read_with(path, [](const std::vector<std::uint8_t>& bytes) { return decode_png(bytes); });
}

Image read_pfm(const std::filesystem::path& path) {
    return read_with(path, [](const std::vector<std::uint8_t>& bytes) { return decode_pfm(bytes); });
}

Image read_exr(const std::filesystem::path& path) {
    return read_with(path, [](const std::vector<std::uint8_t>& bytes) { return decode_exr(bytes); });
}

}  // namespace zeroset
