// The scene's tree in the language: transforms (their order and inverse),
// groups and CSG blocks, shapes placed as instances (shared, not copied),
// loops, the scoping of names in bodies, and the errors of each.
#include <cmath>
#include <numbers>

#include "scene/scene_test_support.hpp"

namespace zeroset::test {
namespace {

constexpr const char* unit_ball = "object { surface x^2 + y^2 + z^2 - 1  bounds box((-1, -1, -1), (1, 1, 1)) ";

Vec3d applied(const Mat4& m, const Vec3d& p) { return m.transform_point(p); }

void expect_near(const Vec3d& a, const Vec3d& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneNodes, TransformsApplyInTheOrderWritten) {
    const Scene s = parse(std::string(unit_ball) + " scale 2  rotate (0, 0, 90)  translate (1, 0, 0) }");
    const PlacedObject o = placed_objects(s).at(0);
    // (1, 0, 0) → scaled (2, 0, 0) → rotated 90° about z (0, 2, 0) → moved (1, 2, 0).
    expect_near(applied(o.to_scene, {1, 0, 0}), {1, 2, 0});
}

TEST(SceneNodes, EveryTransformKind) {
    const auto placed = [](const std::string& t) {
        return placed_objects(parse(std::string(unit_ball) + t + " }")).at(0).to_scene;
    };
    expect_near(applied(placed("rotate 90 around (0, 1, 0)"), {1, 0, 0}), {0, 0, -1});
    expect_near(applied(placed("rotate (90, 0, 0)"), {0, 1, 0}), {0, 0, 1});
    expect_near(applied(placed("scale (1, -2, 3)"), {1, 1, 1}), {1, -2, 3});  // a negative scale mirrors
    expect_near(applied(placed("shear { xy 0.5  zx 2 }"), {1, 2, 3}), {2, 2, 5});
    expect_near(applied(placed("matrix (1, 0, 0, 5,  0, 2, 0, 0,  0, 0, 1, -1)"), {1, 1, 1}), {6, 2, 0});
}

TEST(SceneNodes, GroupsAndCsgBlocksNest) {
    const Scene s = parse(
        "difference \"part\" {\n"
        "  intersection { object { surface x } object { surface y } }\n"
        "  union { object { surface z } }\n"
        "  translate (0, 1, 0)\n"
        "  material { color (1, 0, 0) }\n"
        "}\n"
        "group { object \"a\" { surface x  material { color (0, 1, 0) } } object \"b\" { surface y } }");
    ASSERT_EQ(s.nodes.size(), 2u);
    const SceneNode& part = *s.nodes[0];
    EXPECT_EQ(part.kind, SceneNode::Kind::Difference);
    EXPECT_EQ(part.name, "part");
    ASSERT_EQ(part.children.size(), 2u);
    EXPECT_EQ(part.children[0]->kind, SceneNode::Kind::Intersection);
    EXPECT_EQ(part.children[1]->kind, SceneNode::Kind::Group);
    const std::vector<PlacedObject> objects = placed_objects(s);
    ASSERT_EQ(objects.size(), 5u);
    expect_near(applied(objects[0].to_scene, {0, 0, 0}), {0, 1, 0});
    EXPECT_EQ(objects[0].material.color, (Vec3d{1, 0, 0}));  // from the enclosing block
    EXPECT_EQ(objects[3].name(), "a");
    EXPECT_EQ(objects[3].material.color, (Vec3d{0, 1, 0}));  // its own wins
    EXPECT_EQ(objects[4].material.color, Material{}.color);
}

TEST(SceneNodes, InstancesShareTheirShape) {
    const Scene s = parse("shape bolt {\n" + std::string(unit_ball) +
                          "} }\n"
                          "instance bolt { translate (1, 0, 0) }\n"
                          "instance bolt { translate (2, 0, 0)  material { color (0, 0, 1) } }\n"
                          "instance bolt\n");
    ASSERT_EQ(s.nodes.size(), 3u);
    EXPECT_EQ(s.nodes[0]->children.at(0), s.nodes[1]->children.at(0));  // one shape node, placed three times
    EXPECT_EQ(s.nodes[0]->children.at(0), s.nodes[2]->children.at(0));
    const std::vector<PlacedObject> objects = placed_objects(s);
    ASSERT_EQ(objects.size(), 3u);
    expect_near(applied(objects[1].to_scene, {0, 0, 0}), {2, 0, 0});
    EXPECT_EQ(objects[1].material.color, (Vec3d{0, 0, 1}));
}

TEST(SceneNodes, ShapesWithParametersAreReadOncePerArgumentList) {
    const Scene s = parse(
        "shape ring(R, r) { object { surface (sqrt(x^2 + y^2) - R)^2 + z^2 - r^2  bounds box((-R - r, -R - r, -r), "
        "(R + r, R + r, r)) } }\n"
        "instance ring(1, 0.25)\n"
        "instance ring(2, 0.5)\n"
        "instance ring(1, 0.25) { translate (0, 0, 3) }\n");
    ASSERT_EQ(s.nodes.size(), 3u);
    EXPECT_EQ(s.nodes[0]->children.at(0), s.nodes[2]->children.at(0));
    EXPECT_NE(s.nodes[0]->children.at(0), s.nodes[1]->children.at(0));
    const std::vector<PlacedObject> objects = placed_objects(s);
    EXPECT_EQ(objects[1].object().bounds.box.hi, (Vec3d{2.5, 2.5, 0.5}));
    const Tape tape(objects[1].object().surface);
    Evaluator<double> f(tape);
    EXPECT_NEAR(f(2.5, 0, 0), 0.0, 1e-12);
}

TEST(SceneNodes, AVectorArgumentIsNotThreeNumbers) {
    // s((x, y, z), x, y, z) and s(x, y, z, (x, y, z)) pass the same four
    // expressions in another grouping: each is a reading of its own, so the
    // second (a vector times a vector) is an error, not the first's body.
    const std::string shape = "shape s(a, b, c, d) { object { surface a*a + b*b + c*c - 1  bounds none } }\n";
    const std::string alone = error_of(shape + "instance s((x, y, z), x, y, z)");
    EXPECT_NE(alone.find("cannot apply '*' to two vectors"), std::string::npos) << alone;
    const std::string after = error_of(shape + "instance s(x, y, z, (x, y, z))\ninstance s((x, y, z), x, y, z)");
    EXPECT_NE(after.find("cannot apply '*' to two vectors"), std::string::npos) << after;
    EXPECT_NE(after.find("placed at scene.zs:3:"), std::string::npos) << after;
    // The same arguments again do share a reading.
    const Scene twice = parse("shape t(a, b) { object { surface x*a + y*b  bounds none } }\n"
                              "instance t(1, 2)\ninstance t(1, 2)\ninstance t(2, 1)");
    EXPECT_EQ(twice.nodes[0]->children.at(0), twice.nodes[1]->children.at(0));
    EXPECT_NE(twice.nodes[0]->children.at(0), twice.nodes[2]->children.at(0));
}

TEST(SceneNodes, LoopsRepeatTheirBody) {
    const Scene s = parse(
        "for i from 0 to 4 {\n"
        "  let r = 0.1 * (i + 1)\n"  // a let in a body is bound anew in each iteration
        "  object { surface x^2 + y^2 + z^2 - r^2  bounds box((-1, -1, -1), (1, 1, 1))  translate (i, 0, 0) }\n"
        "}\n"
        "group { for k from 10 to 0 step -5 { object { surface x - k } } }\n"
        "for j from 1 to 0 { object { surface x } }\n");  // runs no time
    const std::vector<PlacedObject> objects = placed_objects(s);
    ASSERT_EQ(objects.size(), 8u);
    expect_near(applied(objects[3].to_scene, {0, 0, 0}), {3, 0, 0});
    const Tape tape(objects[4].object().surface);
    Evaluator<double> f(tape);
    EXPECT_NEAR(f(0.5, 0, 0), 0.25 - 0.25, 1e-12);
    ASSERT_EQ(s.nodes.back()->children.size(), 3u);
}

TEST(SceneNodes, ABodySeesOnlyWhatWasVisibleWhereItIsWritten) {
    // The shape is defined before `late` is bound: reading it later must not see it.
    EXPECT_EQ(error_of("shape s { object { surface x - late } }\nlet late = 1\ninstance s"),
              "scene.zs:1:32: unknown identifier 'late' (in shape 's' placed at scene.zs:3:10)");
    // Loop counters are not visible outside their loop, nor in shapes placed there.
    EXPECT_EQ(error_of("for i from 0 to 1 { }\nobject { surface x - i }"), "scene.zs:2:22: unknown identifier 'i'");
    EXPECT_EQ(error_of("shape s { object { surface x - i } }\nfor i from 0 to 1 { instance s }"),
              "scene.zs:1:32: unknown identifier 'i' (in shape 's' placed at scene.zs:2:30) (in the loop at "
              "scene.zs:2:1 with i = 0)");
    // No name hides another.
    EXPECT_EQ(error_of("let r = 1\nfor r from 0 to 1 { }"),
              "scene.zs:2:5: 'r' is already bound (at scene.zs:1:5); a name can be bound only once");
    EXPECT_EQ(error_of("let r = 1\nshape s(r) { }"),
              "scene.zs:2:9: 'r' is already bound (at scene.zs:1:5); a name can be bound only once");
}

TEST(SceneNodes, AnObjectWithoutBoundsMustBeAPlane) {
    const Scene s = parse("object { surface y + 1  bounds none }");
    EXPECT_EQ(placed_objects(s).at(0).object().bounds.kind, Bounds::Kind::None);
}

TEST(SceneNodes, Errors) {
    EXPECT_EQ(error_of(std::string(unit_ball) + " scale 0 }"),
              "scene.zs:1:82: a scale of 0 would flatten the object; scale by nonzero factors (negative mirrors)");
    EXPECT_EQ(error_of(std::string(unit_ball) + " rotate 30 }"),
              "scene.zs:1:86: expected 'around' and an axis, as in rotate 30 around (0, 1, 0), but found '}'");
    EXPECT_EQ(error_of(std::string(unit_ball) + " shear { xy 1 yx 1 } }"),
              "scene.zs:1:76: shear: the transform is singular or nearly so (|det| / column lengths = 0); it would "
              "flatten the object");
    // A soak run found maps whose inverse overflows (a scale of 1e-320 is
    // "square", but moves rays to ∞) and NaN factors.
    EXPECT_EQ(error_of(std::string(unit_ball) + " scale (1e-320, 1, 1) }"),
              "scene.zs:1:76: scale: the transform or its inverse stretches lengths by more than 1e100 (keep "
              "scale factors between 1e-100 and 1e100)");
    EXPECT_EQ(error_of(std::string(unit_ball) + " scale 1e60 scale 1e60 }"),
              "scene.zs:1:87: scale: the transform or its inverse stretches lengths by more than 1e100 (keep "
              "scale factors between 1e-100 and 1e100)");
    EXPECT_EQ(error_of(std::string(unit_ball) + " scale 0/0 }"), "scene.zs:1:82: the scale must be finite, but it is nan");
    EXPECT_EQ(error_of(std::string(unit_ball) + " scale (1e-300, 1, 1) }"),
              "scene.zs:1:76: scale: the transform or its inverse stretches lengths by more than 1e100 (keep "
              "scale factors between 1e-100 and 1e100)");
    EXPECT_NO_THROW(parse(std::string(unit_ball) + " scale (1e-100, 1, 1e100) }"));
    // A translation, however far, is not singular.
    EXPECT_NO_THROW(parse(std::string(unit_ball) + " translate (1e13, 0, 0) }"));
    EXPECT_NO_THROW(parse(std::string(unit_ball) + " scale 1e-13 translate (1, 0, 0) }"));
    EXPECT_EQ(error_of(std::string(unit_ball) + " matrix (1, 0, 0) }"),
              "scene.zs:1:91: expected ',' (a matrix has 12 numbers: 3 rows of A, each followed by its t) but "
              "found ')'");
    EXPECT_EQ(error_of("difference { }"),
              "scene.zs:1:1: a difference needs at least one object, group or instance");
    EXPECT_EQ(error_of("instance nothing"), "scene.zs:1:10: unknown shape 'nothing'");
    EXPECT_EQ(error_of("let a = 1\ninstance a"), "scene.zs:2:10: 'a' is not a shape");
    EXPECT_EQ(error_of("shape s(a) { }\ninstance s"), "scene.zs:2:10: shape 's' takes 1 argument, but 0 were given");
    EXPECT_EQ(error_of("shape s(a, a) { }"), "scene.zs:1:12: the shape already has a parameter 'a'");
    EXPECT_EQ(error_of("shape s { object { surface x }"),
              "scene.zs:1:31: expected '}' to close the shape body opened at line 1, column 9, but found end of file");
    EXPECT_EQ(error_of("group { camera { } }"),
              "scene.zs:1:9: expected an object, blob, fractal, sweep, group, union, intersection, difference, instance, let, for, a "
              "transform (translate, rotate, scale, shear, matrix), material or '}' but found 'camera'");
    EXPECT_EQ(error_of("for i from 0 to 1e9 { }"), "scene.zs:1:1: the loop would run more than 10000000 times");
    EXPECT_EQ(error_of("for i from 0 to 1 step 0 { }"), "scene.zs:1:24: the loop's step must not be 0");
    EXPECT_EQ(error_of("for i from 0 to x { }"),
              "scene.zs:1:17: the loop's end must be a constant number, but it depends on x");
    std::string deep;
    for (int i = 0; i < 300; ++i) deep += "group { ";
    EXPECT_EQ(error_of(deep), "scene.zs:1:1601: blocks nested too deeply (more than 200 levels)");
}

}  // namespace
}  // namespace zeroset::test

namespace zeroset::test {
namespace {

TEST(SceneNodes, AnIdenticallyZeroSurfaceIsAnError) {
    EXPECT_EQ(error_of("object { surface x - x }"),
              "scene.zs:1:18: the surface is 0 at every point tried in its bounds ((x - x)): it must be negative "
              "inside and positive outside to have an inside at all");
    EXPECT_NE(error_of("object {\n  bounds box((0, 0, 0), (1, 1, 1))\n  surface x*0 }").find("scene.zs:3:11"),
              std::string::npos);
    EXPECT_EQ(error_of("object { surface x * y * z }"), "");  // 0 on planes only
}

}  // namespace
}  // namespace zeroset::test
