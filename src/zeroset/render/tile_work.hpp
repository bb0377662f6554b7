// The unit every scheduler hands out: a tile of the image, and what tracing
// it cost — summed over tiles into a render's stats, logged per tile
// (--tile-log), and sent between the ranks of a distributed render.
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/render/render_stats.hpp"

namespace zeroset {

/// A rectangle of pixels, [x0, x1) × [y0, y1).
struct TileRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    [[nodiscard]] int width() const { return x1 - x0; }
    [[nodiscard]] int height() const { return y1 - y0; }
};

/// The side of the square tiles an image is cut into.
inline constexpr int tile_side = 16;

/// The image's tiles in reading order: rows of tile_side squares, narrower at
/// the right and bottom edges.
std::vector<TileRect> image_tiles(int width, int height);
/// How many tiles image_tiles(width, height) has, and tile `index` of them,
/// without making the list.
std::size_t tile_count(int width, int height);
TileRect tile_at(int width, int height, std::size_t index);

/// What tracing some tiles cost; summed over tiles into the render's stats.
struct TileWork {
    std::uint64_t camera_rays = 0;
    std::uint64_t untraced_camera_rays = 0;  // of those, in tiles proven to see no surface (Primitive::misses_tile)
    std::uint64_t hits = 0;
    std::uint64_t shadow_rays = 0;
    std::uint64_t reflection_rays = 0;
    TraceCounters trace;  // evaluation_limit unused here
    ConeCounters cone;
    double seconds = 0.0;

    TileWork& operator+=(const TileWork& o);
};

}  // namespace zeroset
