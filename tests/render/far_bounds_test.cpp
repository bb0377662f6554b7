// A polynomial surface in bounds far larger than itself — a POV-Ray poly
// without bounded_by, an unbounded sheet in ±10⁴ — must draw as it does in a
// tight box. Its ray polynomials were once formed about the middle of spans
// 10⁴ units long, whose rounding blurred the surface itself: every camera
// ray reported a hit and the image was noise, silently.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

RenderResult draw_steiner(const std::string& bounds, Method method) {
    const std::string text = R"(
camera { from (2.4, -2.0, 1.7)  at (0, 0, 0)  up (0, 0, 1)  fov 24 }
light  { from (-4, -6, 8) }
object "Roman surface" {
  cut on
  surface steiner()
  bounds  )" + bounds + R"(
}
)";
    RenderSettings settings;
    settings.width = 120;
    settings.height = 90;
    settings.method = method;
    return render(parse_scene(text, "far_bounds.zs", "."), settings);
}

TEST(FarBounds, APolynomialSurfaceDrawsAsInATightBox) {
    const std::string far = "box((-1e4, -1e4, -1e4), (1e4, 1e4, 1e4))";
    const RenderResult tight = draw_steiner("box((-0.51, -0.51, -0.51), (0.51, 0.51, 0.51))", Method::Polynomial);
    const RenderResult interval = draw_steiner(far, Method::Interval);
    const RenderResult polynomial = draw_steiner(far, Method::Polynomial);
    ASSERT_GT(tight.stats.hits, 1000u);
    ASSERT_LT(tight.stats.hits, 120u * 90u / 2u);  // the surface covers part of the frame only
    EXPECT_EQ(polynomial.stats.hits, tight.stats.hits);
    EXPECT_EQ(interval.stats.hits, tight.stats.hits);
    // (The shading follows the object's size, taken from its bounds — its
    // shadow rays' offsets, for one — so the far box's image is compared
    // with the interval method's in the same box.)
    int differ = 0;
    for (std::size_t i = 0; i < interval.image.pixels.size(); ++i) {
        const Vec3f d = polynomial.image.pixels[i] - interval.image.pixels[i];
        differ += std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > 1e-3f;
    }
    EXPECT_LE(differ, 2) << "pixels where the polynomial method's image differs from the interval method's";
}

}  // namespace
}  // namespace zeroset
