// The machined part of scenes/csg/ built both ways — one expression with
// min/max (function CSG) and six objects merged by span lists (Roth CSG) —
// covers the same pixels. The plate under it is hidden in both renders, so
// the masks are the part's alone.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/coverage.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

/// The part's pixels: everything but the background, with the plate removed.
std::vector<bool> part_mask(const std::string& file, int width, int height) {
    Scene scene = load_scene(ZEROSET_SOURCE_DIR "/scenes/csg/" + file);
    std::erase_if(scene.nodes, [](const SceneNodePtr& n) { return n->name == "plate"; });
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    return test::coverage(scene, settings);
}

TEST(CsgScenes, FunctionAndRothCsgCoverTheSamePixels) {
    const int width = 200, height = 150;
    const std::vector<bool> function = part_mask("machined_part_function.zs", width, height);
    const std::vector<bool> roth = part_mask("machined_part_roth.zs", width, height);
    int differ = 0, covered = 0;
    for (std::size_t i = 0; i < function.size(); ++i) {
        differ += function[i] != roth[i];
        covered += function[i];
    }
    const double fraction = static_cast<double>(differ) / static_cast<double>(function.size());
    std::printf("machined part, %dx%d: %d of %zu pixels differ (%.3f %%), %d covered\n", width, height, differ,
                function.size(), 100.0 * fraction, covered);
    EXPECT_GT(covered, width * height / 5);
    EXPECT_LE(fraction, 0.001);
}

}  // namespace
}  // namespace zeroset
