// The scenes of scenes/deform/: each renders with sensible coverage, and the
// bounds of its deformed object (the first in the file) hold the whole
// deformed surface — interval arithmetic proves f > 0 all over the bounds'
// faces, where an object cut off by its bounds would show.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene_test_support.hpp"
#include "support/bounds_proof.hpp"
#include "zeroset/render/renderer.hpp"

namespace zeroset {
namespace {

std::vector<std::filesystem::path> deform_scenes() {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/deform"))
        if (entry.path().extension() == ".zs") scenes.push_back(entry.path());
    return scenes;
}

TEST(DeformScenes, BoundsHoldTheDeformedSurface) {
    ASSERT_GE(deform_scenes().size(), 2U);
    for (const auto& path : deform_scenes()) {
        const Scene scene = load_scene(path);
        const Object& object = placed_objects(scene).at(0).object();
        EXPECT_TRUE(test::unproven_faces(object.surface, object.bounds.enclosing_box(), 8).empty())
            << path.filename() << ": the surface may cross its bounds";
    }
}

TEST(DeformScenes, RenderWithSensibleCoverage) {
    for (const auto& path : deform_scenes()) {
        const Scene scene = load_scene(path);
        RenderSettings settings;
        settings.width = 48;
        settings.height = 36;
        const Image image = render(scene, settings).image;
        int object_pixels = 0;
        const Vec3f sky = image.at(0, 0);  // the top-left corner sees the background
        for (int y = 0; y < image.height / 3; ++y)
            for (int x = 0; x < image.width; ++x) {
                const Vec3f p = image.at(x, y);
                object_pixels += std::abs(p.x - sky.x) + std::abs(p.y - sky.y) + std::abs(p.z - sky.z) > 1e-3f;
            }
        // The deformed object reaches into the top third of the frame, and does not fill it.
        const double share = static_cast<double>(object_pixels) / (image.width * (image.height / 3));
        EXPECT_GT(share, 0.05) << path.filename();
        EXPECT_LT(share, 0.7) << path.filename();
    }
}

}  // namespace
}  // namespace zeroset
