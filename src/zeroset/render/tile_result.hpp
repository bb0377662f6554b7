// A rendered tile as it travels from the rank that traced it to rank 0 of a
// distributed render: which frame and tile, what it cost, and its pixels
// (with the depth and normal layers when the image has them).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/math/vec3.hpp"
#include "zeroset/render/image.hpp"
#include "zeroset/render/tile_work.hpp"

namespace zeroset {

struct TileResult {
    std::int32_t frame = 0;
    std::uint32_t tile = 0;
    TileWork work;
    Image pixels;  // the tile's size; its pixel (0, 0) is the tile's corner

    [[nodiscard]] std::string pack() const;
    /// Throws std::runtime_error on bytes pack did not make.
    static TileResult unpack(std::string_view bytes);
};

/// Copies the tile's pixels, and its layers when `image` has them, into the
/// image at the tile's place.
void place_tile(const Image& tile_pixels, const TileRect& where, Image& image);

}  // namespace zeroset
