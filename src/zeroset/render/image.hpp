// Image: the renderer's output, linear-light RGB floats, row 0 at the top,
// with optional layers for compositing: each pixel's depth and normal.
// Writers in io/ encode it (sRGB for 8-bit formats, linear for PFM and EXR;
// only EXR stores the layers).
#pragma once

#include <cstddef>
#include <limits>

#include "zeroset/math/vec3.hpp"
#include "zeroset/render/large_buffer.hpp"

namespace zeroset {

struct Image {
    int width = 0;
    int height = 0;
    LargeBuffer<Vec3f> pixels;  // row-major, width·height
    /// Empty, or width·height entries: the distance from the eye to the
    /// pixel's nearest surface along its ray (+∞ where no sample hit)…
    LargeBuffer<float> depth;
    /// …and the unit normal there, in scene space, facing the eye ((0, 0, 0)
    /// where no sample hit).
    LargeBuffer<Vec3f> normals;

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}

    [[nodiscard]] bool has_layers() const { return !depth.empty(); }
    /// Allocates the depth and normal layers, as for a pixel hit by nothing.
    void add_layers() {
        depth.assign(pixels.size(), std::numeric_limits<float>::infinity());
        normals.assign(pixels.size(), Vec3f{0, 0, 0});
    }

    Vec3f& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
    [[nodiscard]] const Vec3f& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
    }
};

}  // namespace zeroset
