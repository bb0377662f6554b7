// Which pixels of a render show an object rather than the background: the
// masks the whole-render tests compare (two ways of building one object
// must cover the same pixels).
#pragma once

#include <algorithm>
#include <vector>

#include "zeroset/render/renderer.hpp"

namespace zeroset::test {

inline std::vector<bool> coverage(const Scene& scene, const RenderSettings& settings) {
    const RenderResult r = render(scene, settings);
    std::vector<bool> mask;
    const Vec3d bg = scene.background;
    for (const auto& p : r.image.pixels)
        mask.push_back(!(p.x == static_cast<float>(bg.x) && p.y == static_cast<float>(bg.y) &&
                         p.z == static_cast<float>(bg.z)));
    return mask;
}

/// The mask at a size, with the renderer's other settings left as they are.
inline std::vector<bool> coverage(const Scene& scene, int width, int height) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    return coverage(scene, settings);
}

/// The share of the pixels a mask covers.
inline double covered(const std::vector<bool>& mask) {
    return static_cast<double>(std::count(mask.begin(), mask.end(), true)) / static_cast<double>(mask.size());
}

}  // namespace zeroset::test
