// The `sweep` statement: the segments each curve makes of its points, the
// radii, loops inside the block, and its located errors.
#include "scene/scene_test_support.hpp"

#include <stdexcept>

namespace zeroset::test {
namespace {

std::vector<SweptSegment> segments_of(const Scene& scene, std::size_t which = 0) {
    return *placed_objects(scene).at(which).object().sweep;
}

TEST(SweepStatement, ALinearSweepIsOneSegmentPerPairOfPoints) {
    const Scene scene = parse("sweep \"horn\" { curve linear  point (0, 0, 0) radius 0.5  point (1, 2, 0) radius 0.1 "
                              " point (2, 2, 0) radius 0.2  translate (1, 0, 0) }");
    const auto s = segments_of(scene);
    ASSERT_EQ(s.size(), 2U);
    EXPECT_EQ(s[0].degree(), 1);
    EXPECT_EQ(s[0].control()[1], (Vec3d{1, 2, 0}));
    EXPECT_DOUBLE_EQ(s[0].radius_from(), 0.5);
    EXPECT_DOUBLE_EQ(s[0].radius_to(), 0.1);
    EXPECT_DOUBLE_EQ(s[1].radius_to(), 0.2);
    EXPECT_EQ(placed_objects(scene)[0].name(), "horn");
    EXPECT_DOUBLE_EQ(placed_objects(scene)[0].to_scene.transform_point({0, 0, 0}).x, 1.0);
    // The bounds hold every segment's spheres.
    const Box3 box = placed_objects(scene)[0].object().bounds.box;
    EXPECT_DOUBLE_EQ(box.lo.x, -0.5);
    EXPECT_DOUBLE_EQ(box.hi.y, 2.5);  // the first segment's box grows by its larger radius
    EXPECT_THROW(surface_of(placed_objects(scene)[0].object()), std::invalid_argument);
}

TEST(SweepStatement, SplinesAreCutIntoCubicBezierPieces) {
    const std::string square = " point (0, 0, 0) point (1, 0, 0) point (1, 1, 0) point (0, 1, 0) ";
    // Catmull–Rom through the points; open, the first and last only steer.
    const auto open = segments_of(parse("sweep { radius 0.1" + square + "}"));
    ASSERT_EQ(open.size(), 1U);
    EXPECT_EQ(open[0].degree(), 3);
    EXPECT_EQ(open[0].control()[0], (Vec3d{1, 0, 0}));
    EXPECT_EQ(open[0].control()[3], (Vec3d{1, 1, 0}));
    EXPECT_EQ(open[0].control()[1], (Vec3d{1, 0, 0} + Vec3d{1, 1, 0} / 6.0));
    const auto closed = segments_of(parse("sweep { closed on radius 0.1" + square + "}"));
    ASSERT_EQ(closed.size(), 4U);
    EXPECT_EQ(closed[3].control()[3], (Vec3d{0, 0, 0}));
    // The B-spline starts at (p0 + 4 p1 + p2)/6.
    const auto b = segments_of(parse("sweep { curve b_spline radius 0.1" + square + "}"));
    ASSERT_EQ(b.size(), 1U);
    EXPECT_NEAR(b[0].control()[0].x, (0 + 4 + 1) / 6.0, 1e-15);
    EXPECT_NEAR(b[0].control()[0].y, 1 / 6.0, 1e-15);
    // Bézier: 3k + 1 points; the radius goes between each piece's ends.
    const auto bezier = segments_of(parse("sweep { curve bezier radius 0.5 point (0, 0, 0) radius 1 "
                                           "point (1, 0, 0) point (2, 0, 0) point (3, 0, 0) radius 2 "
                                           "point (4, 1, 0) point (5, 1, 0) point (6, 0, 0) radius 3 }"));
    ASSERT_EQ(bezier.size(), 2U);
    EXPECT_DOUBLE_EQ(bezier[0].radius_from(), 1.0);
    EXPECT_DOUBLE_EQ(bezier[0].radius_to(), 2.0);
    EXPECT_DOUBLE_EQ(bezier[1].radius_to(), 3.0);
}

TEST(SweepStatement, PointsMayComeFromLoops) {
    const Scene scene = parse("sweep { curve linear radius 0.2 for i from 0 to 9 { let a = i / 3  point (cos(a), sin(a), i) } }");
    EXPECT_EQ(segments_of(scene).size(), 9U);
    EXPECT_DOUBLE_EQ(segments_of(scene)[8].control()[1].z, 9.0);
}

TEST(SweepStatement, GivesLocatedErrors) {
    EXPECT_EQ(error_of("sweep { curve linear point (0, 0, 0) }"),
              "scene.zs:1:22: this point has no radius: give the sweep one (radius R, before its points) or the point "
              "its own (point (x, y, z) radius R)");
    EXPECT_EQ(error_of("sweep { curve linear radius 1 point (0, 0, 0) }"),
              "scene.zs:1:31: sweep: a linear sweep needs at least 2 points");
    EXPECT_EQ(error_of("sweep { radius 1 point (0, 0, 0) point (1, 0, 0) point (2, 0, 0) }"),
              "scene.zs:1:18: sweep: an open spline sweep needs at least 4 points");
    EXPECT_EQ(error_of("sweep { curve bezier radius 1 point (0, 0, 0) point (1, 0, 0) point (2, 0, 0) point (3, 0, 0) "
                       "point (4, 0, 0) }"),
              "scene.zs:1:31: sweep: a bezier sweep needs 3k + 1 points (4, 7, 10, …), not 5");
    EXPECT_EQ(error_of("sweep { curve bezier radius 1 point (0, 0, 0) point (1, 0, 0) radius 3 point (2, 0, 0) "
                       "point (3, 0, 0) }"),
              "scene.zs:1:63: a Bézier control point takes no radius: the radius goes linearly from each piece's "
              "first point to its last");
    EXPECT_EQ(error_of("sweep { curve linear point (0, 0, 0) radius 1 radius 2 }"),
              "scene.zs:1:47: the sweep's radius must come before its points (a radius after a point is that point's own)");
    EXPECT_EQ(error_of("sweep { radius 0 }"), "scene.zs:1:16: the sweep's radius must be positive");
    EXPECT_EQ(error_of("sweep { curve linear point (0, 0, 0) radius -1 point (1, 0, 0) radius 1 }"),
              "scene.zs:1:45: a point's radius must not be negative");
    EXPECT_EQ(error_of("sweep { curve linear point (0, 0, 0) radius 0 point (1, 0, 0) radius 0 }"),
              "scene.zs:1:22: sweep: a swept sphere's radius must not be 0 at both ends");
    EXPECT_EQ(error_of("sweep { curve linear closed on closed off }"),
              "scene.zs:1:32: 'closed' is already set in this sweep block (at line 1, column 22)");
    EXPECT_NE(error_of("sweep { curve spiral }").find("scene.zs:1:15"), std::string::npos);
    EXPECT_NE(error_of("sweep { colour (1, 0, 0) }").find("scene.zs:1:9: expected a key (curve, closed, radius, point or material)"),
              std::string::npos)
        << error_of("sweep { colour (1, 0, 0) }");
}

}  // namespace
}  // namespace zeroset::test
