// The sweep scenes of scenes/sweeps/ rendered small: each shows its tubes,
// and a linear sweep covers the same pixels as the capsule written as a
// distance expression and traced by the interval method.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "support/coverage.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

using test::coverage;
using test::covered;

TEST(SweepScenes, EveryOneShowsItsTubes) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/sweeps")) {
        Scene scene = load_scene(entry.path());
        // The tubes alone: without the floor, what is covered is the sweeps.
        std::erase_if(scene.nodes, [](const SceneNodePtr& n) { return !n->object.sweep; });
        const double part = covered(coverage(scene, 96, 72));
        std::printf("%s: %.1f %% of the pixels covered\n", entry.path().filename().c_str(), 100.0 * part);
        EXPECT_GT(part, 0.05) << entry.path();
        EXPECT_LT(part, 0.6) << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 2);
}

TEST(SweepScenes, ALinearSweepCoversWhatItsCapsuleCovers) {
    const std::string view = "camera { from (0.5, 1, -5) at (0, 0, 0) fov 40 }\n";
    const Scene sweep = parse_scene(view + "sweep { curve linear radius 0.4 point (-1, -0.5, 0) point (1, 0.6, 0.3) }", "s.zs", ".");
    const Scene capsule = parse_scene(view + "object { surface sd_capsule((-1, -0.5, 0), (1, 0.6, 0.3), 0.4) "
                                             "bounds box((-1.5, -1, -0.5), (1.5, 1.1, 0.8)) method interval }",
                                      "c.zs", ".");
    const std::vector<bool> a = coverage(sweep, 160, 120), b = coverage(capsule, 160, 120);
    int differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    EXPECT_GT(covered(a), 0.05);
    EXPECT_EQ(differ, 0);
}

/// Pixels whose coverage differs between two scenes' renders at 160×120.
int differing_pixels(const std::string& a, const std::string& b) {
    const std::string view = "camera { from (0.3, 0.8, -6) at (0, 0, 0) fov 40 }\n";
    const std::vector<bool> x = coverage(parse_scene(view + a, "a.zs", "."), 160, 120);
    const std::vector<bool> y = coverage(parse_scene(view + b, "b.zs", "."), 160, 120);
    EXPECT_GT(covered(x), 0.02);
    int differ = 0;
    for (std::size_t i = 0; i < x.size(); ++i) differ += x[i] != y[i];
    return differ;
}

TEST(SweepScenes, StraightSplinesAndRadiusStepsCoverTheirCapsules) {
    // A Catmull–Rom through collinear, unevenly spaced points runs straight.
    EXPECT_EQ(differing_pixels("sweep { radius 0.3 point (-3.1, 0.1, 0) point (-1.3, 0.1, 0) point (0.7, 0.1, 0) point (2.9, 0.1, 0) }",
                               "object { surface sd_capsule((-1.3, 0.1, 0), (0.7, 0.1, 0), 0.3) "
                               "bounds box((-1.7, -0.3, -0.4), (1.1, 0.5, 0.4)) method interval }"),
              0);
    // A repeated point steps the radius: a piece of length 0 between two capsules.
    EXPECT_EQ(differing_pixels("sweep { curve linear point (-1.5, 0, 0) radius 0.2 point (0, 0, 0) radius 0.2 "
                               "point (0, 0, 0) radius 0.6 point (1.5, 0, 0) radius 0.6 }",
                               "object { surface min(sd_capsule((-1.5, 0, 0), (0, 0, 0), 0.2), sd_capsule((0, 0, 0), (1.5, 0, 0), 0.6)) "
                               "bounds box((-2, -0.7, -0.7), (2.2, 0.7, 0.7)) method interval }"),
              0);
}

TEST(SweepScenes, AMethodOtherThanItsOwnIsRefused) {
    const Scene scene = parse_scene("sweep \"tube\" { curve linear radius 0.4 point (0, 0, 0) point (1, 0, 0) }", "s.zs", ".");
    RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.method = Method::Interval;
    try {
        render(scene, settings);
        FAIL() << "rendered a sweep with the interval method";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("object 'tube' is a sweep, traced exactly by its segments' polynomials"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace zeroset
