// The fractal scenes of scenes/fractals/ rendered small: each one shows its
// fractal, and the Julia set of z² (c = 0), the unit ball, covers the pixels
// the ball written as an expression covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "support/coverage.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

using test::coverage;
using test::covered;

TEST(FractalScenes, EveryOneShowsItsFractal) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/fractals")) {
        const double part = covered(coverage(load_scene(entry.path()), 96, 72));
        std::printf("%s: %.1f %% of the pixels covered\n", entry.path().filename().c_str(), 100.0 * part);
        EXPECT_GT(part, 0.05) << entry.path();
        EXPECT_LT(part, 0.9) << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 2);
}

TEST(FractalScenes, TheJuliaSetOfZSquaredIsTheUnitBall) {
    const std::string view = "camera { from (0.5, 1, -4) at (0, 0, 0) fov 40 }\n";
    const std::vector<bool> julia = coverage(parse_scene(view + "fractal { c (0, 0, 0) iterations 30 }", "j.zs", "."), 160, 120);
    const std::vector<bool> ball = coverage(
        parse_scene(view + "object { surface x^2 + y^2 + z^2 - 1 bounds box((-1, -1, -1), (1, 1, 1)) }", "b.zs", "."), 160, 120);
    int differ = 0;
    for (std::size_t i = 0; i < ball.size(); ++i) differ += julia[i] != ball[i];
    EXPECT_GT(covered(ball), 0.1);
    std::printf("julia of z²: %d of %zu pixels differ from the ball's\n", differ, ball.size());
    // The fractal is drawn grown by its hit tolerance (a pixel): a few rim pixels may differ.
    EXPECT_LE(differ, static_cast<int>(ball.size() / 200)) << differ << " pixels differ";
}

}  // namespace
}  // namespace zeroset
