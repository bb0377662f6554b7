// Packing a tile result, and copying a tile's pixels into the whole image.
#include "zeroset/render/tile_result.hpp"

#include <stdexcept>

#include "zeroset/math/byte_buffer.hpp"

namespace zeroset {

std::string TileResult::pack() const {
    ByteWriter out;
    out.put(frame);
    out.put(tile);
    out.put(work);
    out.put<std::int32_t>(pixels.width);
    out.put<std::int32_t>(pixels.height);
    out.put_vector(pixels.pixels);
    out.put_vector(pixels.depth);
    out.put_vector(pixels.normals);
    return out.take();
}

TileResult TileResult::unpack(std::string_view bytes) {
    ByteReader in(bytes, "the tile results a rank sent");
    TileResult r;
    r.frame = in.get<std::int32_t>();
    r.tile = in.get<std::uint32_t>();
    r.work = in.get<TileWork>();
    r.pixels.width = in.get<std::int32_t>();
    r.pixels.height = in.get<std::int32_t>();
    r.pixels.pixels = in.get_vector<Vec3f, LargeBuffer<Vec3f>>();
    r.pixels.depth = in.get_vector<float, LargeBuffer<float>>();
    r.pixels.normals = in.get_vector<Vec3f, LargeBuffer<Vec3f>>();
    in.expect_end();
    const auto count = static_cast<std::size_t>(r.pixels.width) * static_cast<std::size_t>(r.pixels.height);
    if (r.pixels.width < 0 || r.pixels.height < 0 || r.pixels.pixels.size() != count ||
        (r.pixels.has_layers() && (r.pixels.depth.size() != count || r.pixels.normals.size() != count)))
        throw std::runtime_error("the tile results a rank sent are damaged: their sizes disagree");
    return r;
}

void place_tile(const Image& tile_pixels, const TileRect& where, Image& image) {
    const bool layers = image.has_layers() && tile_pixels.has_layers();
    for (int y = 0; y < where.height(); ++y) {
        for (int x = 0; x < where.width(); ++x) {
            const std::size_t from = static_cast<std::size_t>(y) * static_cast<std::size_t>(tile_pixels.width) +
                                     static_cast<std::size_t>(x);
            const std::size_t to = static_cast<std::size_t>(where.y0 + y) * static_cast<std::size_t>(image.width) +
                                   static_cast<std::size_t>(where.x0 + x);
            image.pixels[to] = tile_pixels.pixels[from];
            if (layers) {
                image.depth[to] = tile_pixels.depth[from];
                image.normals[to] = tile_pixels.normals[from];
            }
        }
    }
}

}  // namespace zeroset
