// Materials beyond one colour — a colour pattern of the object's
// coordinates, a mirror share — the image's reflection depth, and the
// animation clock, as the scene language reads them.
#include <gtest/gtest.h>

#include "scene/scene_test_support.hpp"

namespace zeroset {
namespace {

using test::error_of;
using test::parse;

const Material& material_of(const Scene& scene) { return *scene.nodes.at(0)->material; }

TEST(Materials, AColorWithXYZIsAPatternAndAConstantOneIsAColor) {
    const Scene s = parse("object { surface y  material { color (x, 0.5, mod(floor(z), 2))  reflection 0.25 } }");
    const Material& m = material_of(s);
    ASSERT_TRUE(m.color_pattern);
    EXPECT_EQ(m.reflection, 0.25);
    const Tape blue_tape((*m.color_pattern)[2]);
    Evaluator<double> blue(blue_tape);
    EXPECT_EQ(blue(0, 0, 1.5), 1.0);
    EXPECT_EQ(blue(0, 0, 2.5), 0.0);
    const Scene c = parse("object { surface y  material { color (0.2, 0.5, 1) * 0.5 } }");
    EXPECT_FALSE(material_of(c).color_pattern);
    EXPECT_EQ(material_of(c).color, (Vec3d{0.1, 0.25, 0.5}));
    EXPECT_EQ(material_of(c).reflection, 0.0);
}

TEST(Materials, BadColorsAndReflectionsAreLocated) {
    EXPECT_EQ(error_of("object { surface y  material { color (0.5, -1, 0) } }"),
              "scene.zs:1:38: the material color must not have negative components, but it is (0.5, -1, 0)");
    EXPECT_NE(error_of("object { surface y  material { color x } }").find("scene.zs:1:38: the material color"),
              std::string::npos);
    EXPECT_EQ(error_of("object { surface y  material { reflection 1.5 } }"),
              "scene.zs:1:43: reflection must be between 0 and 1, but it is 1.5");
}

TEST(ImageBlock, ReflectionDepthIsAWholeNumberFromZero) {
    EXPECT_EQ(parse("").image.reflection_depth, 5);
    EXPECT_EQ(parse("image { reflection_depth 0 }").image.reflection_depth, 0);
    EXPECT_EQ(error_of("image { reflection_depth -1 }"),
              "scene.zs:1:26: reflection_depth must be a whole number, at least 0, but it is -1");
    EXPECT_EQ(error_of("image { reflection_depth 65 }"), "scene.zs:1:26: reflection_depth must be at most 64, but it is 65");
}

TEST(ImageBlock, AntialiasIsSamplesOrCone) {
    EXPECT_FALSE(parse("").image.cone_antialiasing);
    EXPECT_TRUE(parse("image { antialias cone }").image.cone_antialiasing);
    EXPECT_FALSE(parse("image { antialias samples }").image.cone_antialiasing);
    EXPECT_NE(error_of("image { antialias cones }").find("scene.zs:1:19:"), std::string::npos)
        << error_of("image { antialias cones }");
}

TEST(Clock, ReadsTheValueTheSceneIsLoadedWith) {
    const std::string text = "let r = 1 + clock\nobject { surface x^2 + y^2 + z^2 - r^2 }\n";
    const auto f_at = [&](double clock, double px) {
        const Scene s = parse_scene(text, "scene.zs", ".", {}, clock);
        const Tape tape(placed_objects(s).at(0).object().surface);
        Evaluator<double> f(tape);
        return f(px, 0, 0);
    };
    EXPECT_EQ(f_at(0.0, 1.0), 0.0);
    EXPECT_EQ(f_at(0.5, 1.5), 0.0);
    EXPECT_EQ(error_of("let clock = 2"), "scene.zs:1:5: 'clock' is a built-in name; it cannot be bound");
    EXPECT_EQ(error_of("object { surface clock(1) }"), "scene.zs:1:18: 'clock' is not a function");
}

}  // namespace
}  // namespace zeroset
