// The one-ray inspector (`zeroset ray`) probes a ray as the renderer traces
// it: the same search region, so the same span and tolerances.
#include <gtest/gtest.h>

#include <array>

#include "zeroset/render/ray_probe.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

// An open sphere clipped where x > 0.5: nothing is drawn beyond the clip, so
// the renderer narrows the bounds to x ≤ 0.5 (about), and the inspector's
// span must end there too.
TEST(RayProbe, AClippedOpenObjectIsSearchedInTheRenderersNarrowedBounds) {
    const Scene scene = parse_scene(R"(
object "cap" {
  open on
  surface x^2 + y^2 + z^2 - 1
  clip x - 0.5
  bounds box((-10, -10, -10), (10, 10, 10))
}
)",
                                    "probe.zs", ".");
    const ObjectProbe probe(placed_objects(scene).at(0), std::nullopt);
    const std::array<Method, 1> methods{Method::Interval};
    const RayProbe along_x = probe.probe(Ray{{-20.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, methods);
    ASSERT_TRUE(along_x.span);
    // Both shrunk to the sphere (x ≥ −1) — and, narrowed by the clip, ending
    // near x = 0.5 rather than at the sphere's x = 1.
    EXPECT_NEAR(along_x.span->t0, 19.0, 0.01);
    EXPECT_GT(along_x.span->t1, 20.49);
    EXPECT_LT(along_x.span->t1, 20.6);
}

// A plane without bounds (the renderer's half-space) is probed about where
// the ray meets it: every method finds that hit, a ray from inside hits at
// its start, one that never meets the plane has no span, and a curved
// surface without bounds is refused as the renderer refuses it.
TEST(RayProbe, APlaneWithoutBoundsIsProbedWhereTheRayMeetsIt) {
    const Scene scene = parse_scene(R"(
object "floor" {
  surface y + 1
  bounds none
}
object "bowl" {
  surface y - x^2
  bounds none
}
)",
                                    "probe.zs", ".");
    const ObjectProbe probe(placed_objects(scene).at(0), std::nullopt);
    const std::array<Method, 4> methods{Method::Interval, Method::Lg, Method::Sphere, Method::Polynomial};
    const RayProbe down = probe.probe(Ray{{0.0, 2.0, 0.0}, {0.0, -1.0, 0.1}}, methods);
    ASSERT_TRUE(down.span);
    EXPECT_TRUE(down.unbounded);
    for (const MethodOutcome& o : down.methods) {
        SCOPED_TRACE(method_label(o));
        ASSERT_TRUE(o.first_hit);
        EXPECT_NEAR(*o.first_hit, 3.0, 1e-9);
        ASSERT_EQ(o.hits.size(), 1u);
    }
    const RayProbe inside = probe.probe(Ray{{0.0, -2.0, 0.0}, {0.0, -1.0, 0.0}}, methods);
    ASSERT_TRUE(inside.span);
    for (const MethodOutcome& o : inside.methods) EXPECT_EQ(o.first_hit, std::optional<double>(0.0)) << method_label(o);
    const RayProbe away = probe.probe(Ray{{0.0, 2.0, 0.0}, {0.0, 1.0, 0.0}}, methods);
    EXPECT_FALSE(away.span);
    const RayProbe along = probe.probe(Ray{{0.0, 2.0, 0.0}, {1.0, 0.0, 0.0}}, methods);
    EXPECT_FALSE(along.span);
    EXPECT_THROW(ObjectProbe(placed_objects(scene).at(1), std::nullopt), std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
