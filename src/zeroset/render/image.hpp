// Image: the renderer's output, linear-light RGB floats, row 0 at the top.
// Writers in io/ encode it (sRGB for 8-bit formats, linear for PFM).
#pragma once

#include <cstddef>
#include <vector>

#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Vec3f> pixels;  // row-major, width·height

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}

    Vec3f& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
    [[nodiscard]] const Vec3f& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
    }
};

}  // namespace zeroset
