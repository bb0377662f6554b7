// The one check every encoder makes before touching pixels: a positive size
// and exactly width·height pixels (and layer entries, when there are
// layers). A malformed Image must give a clear error, never an out-of-bounds
// read or an empty file.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// Throws std::invalid_argument describing what is wrong with the image's shape.
inline void require_valid_image(const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument("invalid image size " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " (width and height must be positive)");
    const std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    if (image.pixels.size() != expected)
        throw std::invalid_argument("image has " + std::to_string(image.pixels.size()) + " pixels, expected " +
                                    std::to_string(image.width) + "x" + std::to_string(image.height) + " = " +
                                    std::to_string(expected));
    if (!image.depth.empty() || !image.normals.empty())
        if (image.depth.size() != expected || image.normals.size() != expected)
            throw std::invalid_argument("image layers have " + std::to_string(image.depth.size()) + " depths and " +
                                        std::to_string(image.normals.size()) + " normals, expected " +
                                        std::to_string(expected) + " of each");
}

}  // namespace zeroset
