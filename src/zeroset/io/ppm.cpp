// P6 encoder: a text header, then one byte per channel; sRGB like PNG, since
// PPM viewers display the bytes as they are.
#include "zeroset/io/ppm.hpp"

#include <string>

#include "zeroset/io/image_shape.hpp"
#include "zeroset/io/srgb.hpp"

namespace zeroset {

std::vector<std::uint8_t> encode_ppm(const Image& image) {
    require_valid_image(image);
    const std::string header = "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    std::vector<std::uint8_t> out;
    out.reserve(header.size() + 3 * image.pixels.size());
    out.insert(out.end(), header.begin(), header.end());
    for (const Vec3f& p : image.pixels) {
        out.push_back(encode_srgb8(p.x));
        out.push_back(encode_srgb8(p.y));
        out.push_back(encode_srgb8(p.z));
    }
    return out;
}

}  // namespace zeroset
