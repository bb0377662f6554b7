// The `fractal` statement: what it reads, its located errors, and that a
// fractal, which has no expression, says so where one is asked for.
#include "scene/scene_test_support.hpp"

#include <stdexcept>

namespace zeroset::test {
namespace {

TEST(FractalStatement, ReadsAJuliaSetAndAMandelbulb) {
    const Scene scene = parse(
        "fractal \"j\" { kind julia c (-0.8, 0.16, 0.1) ck 0.05 slice 0.2 iterations 20 detail 2 scale 1.5 }\n"
        "fractal \"m\" { kind mandelbulb power 6 iterations 8 }\n");
    const auto placed = placed_objects(scene);
    ASSERT_EQ(placed.size(), 2U);
    const FractalParameters& j = placed[0].object().fractal->parameters();
    EXPECT_EQ(j.kind, FractalKind::QuaternionJulia);
    EXPECT_DOUBLE_EQ(j.c.r, -0.8);
    EXPECT_DOUBLE_EQ(j.c.j, 0.1);
    EXPECT_DOUBLE_EQ(j.c.k, 0.05);
    EXPECT_DOUBLE_EQ(j.slice, 0.2);
    EXPECT_EQ(j.iterations, 20);
    EXPECT_DOUBLE_EQ(placed[0].object().fractal_detail, 2.0);
    EXPECT_DOUBLE_EQ(placed[0].to_scene.transform_point({1, 0, 0}).x, 1.5);
    EXPECT_EQ(placed[1].object().fractal->parameters().kind, FractalKind::Mandelbulb);
    EXPECT_DOUBLE_EQ(placed[1].object().fractal->parameters().power, 6.0);
    EXPECT_THROW(surface_of(placed[1].object()), std::invalid_argument);
}

TEST(FractalStatement, GivesLocatedErrors) {
    EXPECT_EQ(error_of("fractal { kind julia power 3 }"),
              "scene.zs:1:22: 'power' is for Mandelbulbs (kind mandelbulb)");
    EXPECT_EQ(error_of("fractal { kind mandelbulb c (1, 0, 0) }"), "scene.zs:1:27: 'c' is for Julia sets (kind julia)");
    EXPECT_EQ(error_of("fractal { kind mandelbulb power 1 }"), "scene.zs:1:33: the power must be between 2 and 16");
    EXPECT_EQ(error_of("fractal { detail 0 }"),
              "scene.zs:1:18: the detail (the hit tolerance, in pixels) must be positive");
    EXPECT_NE(error_of("fractal { slice 9 }").find("scene.zs:1:1: fractal: the slice k = 9"), std::string::npos)
        << error_of("fractal { slice 9 }");
    EXPECT_NE(error_of("fractal { kind cantor }").find("scene.zs:1:16"), std::string::npos);
    EXPECT_NE(error_of("fractal { iterations 1000 }").find("scene.zs:1:22"), std::string::npos);
}

}  // namespace
}  // namespace zeroset::test
