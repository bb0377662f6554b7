// --tile-log: what every tile of a render cost, one CSV row per tile, for
// finding the costly regions of a scene and for modelling how a render
// spreads over many machines (bench/simulate_distributed.py).
#pragma once

#include <filesystem>
#include <string>

#include "zeroset/render/tile_work.hpp"

namespace zeroset::cli {

class TileLog {
public:
    /// Throws FileWriteError unless the log could be written at `path` now
    /// (checked before rendering, as the image's place is).
    static void check(const std::filesystem::path& path);

    /// Records one tile of `frame`, traced by `rank` (0 outside a distributed render).
    void add(std::size_t frame, int rank, const TileRect& tile, const TileWork& work);
    /// Writes the rows, after a header line, atomically (FileWriteError).
    void write(const std::filesystem::path& path) const;

private:
    std::string rows_;
};

}  // namespace zeroset::cli
