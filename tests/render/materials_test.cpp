// Colour patterns and mirror reflection in the image: a checker evaluated at
// every hit, in the object's own coordinates; a mirror that shows what is
// in front of it, as deep as the scene allows and no deeper.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

RenderSettings small(bool layers = false) {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.threads = 2;
    s.layers = layers;
    return s;
}

float brightness(const Vec3f& c) { return c.x + c.y + c.z; }

TEST(ColorPatterns, ACheckerIsEvaluatedAtEveryHit) {
    // Straight down at a checkered floor, lit straight from above with no
    // shadows or highlights: every pixel is one of the two colours exactly.
    const Scene scene = parse_scene(R"(
        camera { from (0.3, 6, 0.2)  at (0.3, 0, 0.2)  up (0, 0, 1) }
        light  { direction (0, -1, 0)  shadows off }
        object { surface y  bounds none
                 material { color (0.2, 0.2, 0.2) + (0.6, 0.6, 0.6) * mod(floor(x) + floor(z), 2)  specular 0 } }
    )", "checker.zs", ".");
    const Image image = render(scene, small()).image;
    int light = 0, dark = 0;
    for (const Vec3f& p : image.pixels) {
        const float b = brightness(p);
        if (std::abs(b - 3 * 0.8f) < 1e-5f) ++light;
        else if (std::abs(b - 3 * 0.2f) < 1e-5f) ++dark;
        else ADD_FAILURE() << "a pixel of neither colour: " << b;
    }
    const double share = static_cast<double>(light) / (light + dark);
    EXPECT_GT(share, 0.3);
    EXPECT_LT(share, 0.7);
}

TEST(ColorPatterns, ThePatternMovesWithItsObject) {
    // Dark where the object's own x < 0, bright where x > 0, the ball moved
    // far to the right: its left half stays dark.
    const Scene scene = parse_scene(R"(
        camera { from (5, 0, -6)  at (5, 0, 0) }
        object { surface x^2 + y^2 + z^2 - 1  bounds box((-1.1, -1.1, -1.1), (1.1, 1.1, 1.1))
                 material { color (1, 1, 1) * clamp(1000 * x, 0, 1)  specular 0 }
                 translate (5, 0, 0) }
    )", "moved.zs", ".");
    const Image image = render(scene, small()).image;
    EXPECT_LT(brightness(image.at(26, 24)), 0.5f * brightness(image.at(38, 24)));
    EXPECT_EQ(brightness(image.at(26, 24)), 0.0f);  // albedo 0 there: no light at all
}

std::string mirror_scene(double reflection, int depth) {
    return "image { reflection_depth " + std::to_string(depth) + " }\n"
           "camera { from (0, 1, -6)  at (0, 0, 0) }\n"
           "light { from (-3, 5, -3) }\n"
           "object \"mirror\" { surface y + 1  bounds none\n"
           "  material { color (0, 0, 0)  ambient 0  diffuse 0  specular 0  reflection " +
           std::to_string(reflection) + " } }\n"
           "object \"ball\" { surface x^2 + y^2 + z^2 - 0.5  bounds box((-1, -1, -1), (1, 1, 1))\n"
           "  material { color (1, 0, 0)  specular 0 } }\n";
}

TEST(Reflection, AMirrorShowsWhatIsInFrontOfIt) {
    const RenderResult flat = render(parse_scene(mirror_scene(0.0, 5), "m.zs", "."), small(true));
    const RenderResult mirror = render(parse_scene(mirror_scene(1.0, 5), "m.zs", "."), small(true));
    EXPECT_EQ(flat.stats.reflection_rays, 0u);
    EXPECT_GT(mirror.stats.reflection_rays, 0u);
    int red = 0, sky = 0;
    for (std::size_t i = 0; i < flat.image.pixels.size(); ++i) {
        if (std::abs(flat.image.normals[i].y - 1.0f) > 1e-6f) continue;  // not the mirror
        EXPECT_EQ(brightness(flat.image.pixels[i]), 0.0f);                // a black floor without reflection
        const Vec3f p = mirror.image.pixels[i];
        if (p.x > 0.05f && p.y < 1e-6f && p.z < 1e-6f) ++red;  // the ball's image
        else if (p.z > p.x) ++sky;                            // the background's
    }
    EXPECT_GT(red, 20);
    EXPECT_GT(sky, 200);
}

TEST(Reflection, NoBouncesLeftMeansNoReflection) {
    const RenderResult flat = render(parse_scene(mirror_scene(0.0, 5), "m.zs", "."), small());
    const RenderResult none = render(parse_scene(mirror_scene(1.0, 0), "m.zs", "."), small());
    EXPECT_EQ(none.stats.reflection_rays, 0u);
    for (std::size_t i = 0; i < flat.image.pixels.size(); ++i) ASSERT_EQ(flat.image.pixels[i], none.image.pixels[i]) << i;
}

TEST(Reflection, FacingMirrorsStopAtTheDepth) {
    // Between two parallel mirrors a ray bounces for ever: the depth ends it.
    const Scene scene = parse_scene(R"(
        image { reflection_depth 7 }
        camera { from (0, 0, -0.5)  at (0.3, 0, 1) }
        object { surface x - 1  bounds none  material { reflection 1 } }
        object { surface -1 - x  bounds none  material { reflection 1 } }
    )", "facing.zs", ".");
    const RenderResult r = render(scene, small());
    EXPECT_GT(r.stats.reflection_rays, r.stats.camera_rays);
    EXPECT_LE(r.stats.reflection_rays, 7 * r.stats.camera_rays);
    Scene deep = scene;
    deep.image.reflection_depth = max_reflection_depth + 1;  // built in C++: the renderer still refuses it
    EXPECT_THROW(render(deep, small()), RenderError);
}

}  // namespace
}  // namespace zeroset
