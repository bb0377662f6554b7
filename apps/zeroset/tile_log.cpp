// The tile log's rows, written as one CSV file.
#include "tile_log.hpp"

#include <cstdint>
#include <cstdio>
#include <span>

#include "zeroset/io/atomic_file.hpp"

namespace zeroset::cli {

void TileLog::check(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw FileWriteError(path, "is a directory");
    const AtomicFile probe(path);  // created now, removed when it goes out of scope
}

void TileLog::add(std::size_t frame, int rank, const TileRect& tile, const TileWork& work) {
    char row[256];
    std::snprintf(row, sizeof row, "%zu,%d,%d,%d,%d,%d,%.9f,%llu,%llu,%llu\n", frame, tile.x0, tile.y0, tile.width(),
                  tile.height(), rank, work.seconds, static_cast<unsigned long long>(work.trace.evaluations()),
                  static_cast<unsigned long long>(work.camera_rays), static_cast<unsigned long long>(work.hits));
    rows_ += row;
}

void TileLog::write(const std::filesystem::path& path) const {
    const std::string text = "frame,x0,y0,width,height,rank,seconds,evaluations,camera_rays,hits\n" + rows_;
    write_file_atomically(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace zeroset::cli
