// Issue 9, defect 1, as a user sees it: the same scene with bounds a little
// and a hundred million times wider than its surface renders the same image.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

Image render_with_bounds(const std::string& method, const std::string& half) {
    const std::string text = "camera { from (0, 0.5, 5)  at (0, 0, 0)  fov 40 }\n"
                             "light  { from (3, 4, 5) }\n"
                             "object { surface x^2 + y^2 + z^2 - 1  method " + method +
                             "  bounds box((-" + half + ", -" + half + ", -" + half + "), (" + half + ", " + half +
                             ", " + half + ")) }\n"
                             "object { surface (x - 1.2)^2 + (y + 0.8)^2 + z^2 - 0.09  method " + method +
                             "  bounds box((-" + half + ", -" + half + ", -" + half + "), (" + half + ", " + half +
                             ", " + half + ")) }\n";
    const Scene scene = parse_scene(text, "loose.zs", ".");
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    return render(scene, settings).image;
}

TEST(LooseBoundsImage, WideBoundsRenderTheSameImage) {
    for (const std::string method : {"auto", "sphere", "interval", "lg"}) {
        const Image tight = render_with_bounds(method, "1.6");
        const Image loose = render_with_bounds(method, "1e8");
        ASSERT_EQ(tight.pixels.size(), loose.pixels.size());
        double worst = 0.0;
        int covered = 0;
        for (std::size_t i = 0; i < tight.pixels.size(); ++i) {
            const Vec3f d = tight.pixels[i] - loose.pixels[i];
            worst = std::max({worst, double(std::abs(d.x)), double(std::abs(d.y)), double(std::abs(d.z))});
            covered += tight.pixels[i] != tight.pixels[0];
        }
        EXPECT_GT(covered, 500) << method << ": the balls are in the picture";
        EXPECT_LT(worst, 1e-4) << method << ": the largest difference of a colour channel";
    }
}

}  // namespace
}  // namespace zeroset
