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

}  // namespace
}  // namespace zeroset
