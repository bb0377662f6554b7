// Frustum culling (accel/frustum_cull.hpp) only moves where a camera ray
// starts looking, and a polynomial leaf's tile proofs only skip rays that
// miss: every image is the same with them as without — for partitioned
// objects seen directly and through instances, cut by their bounds, and
// with several rays a pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

// Sixteen spheres in a ring, blended with a torus: a tape of well over 64
// clauses, which `auto` partitions. The second placement is the same shape
// turned and squashed by an instance; the third object is cut by its bounds.
std::string scene_text() {
    std::string ring;
    for (int k = 0; k < 16; ++k) {
        const std::string a = std::to_string(k) + " * pi / 8";
        const std::string sphere = "sqrt((x - 1.6 * cos(" + a + "))^2 + (y - 0.25 * sin(2 * " + a +
                                   "))^2 + (z - 1.6 * sin(" + a + "))^2) - 0.22 - 0.08 * cos(" + std::to_string(k) + ")";
        ring = k == 0 ? sphere : "min(" + ring + ", " + sphere + ")";
    }
    const std::string surface = "smooth_union(" + ring + ", sqrt((sqrt(x^2 + z^2) - 1.6)^2 + y^2) - 0.12, 0.1)";
    return R"(
image  { width 64  height 48  spp 2 }
camera { from (0.4, 2.6, -6)  at (0, 0, 0)  fov 38 }
light  { from (-4, 6, -5) }
shape beads {
  object { surface )" + surface + R"(  bounds box((-2, -0.6, -2), (2, 0.6, 2))  method sphere
           material { color (0.8, 0.5, 0.3) } }
}
instance beads { translate (0, 0.4, 0) }
instance beads { scale (0.6, 0.8, 1.1)  rotate (50, 20, 0)  translate (0.3, -0.9, 0.5) }
object "cut" {
  surface )" + surface + R"(
  bounds box((-2, -0.1, -2), (0.5, 0.6, 2))
  method sphere
  rotate (0, 30, 0)  translate (0, -1.6, 1)
}
)";
}

/// The scene at its own size and samples, on two threads (with the depth
/// and normal layers when asked): with frustum culling, then without.
std::pair<RenderResult, RenderResult> render_with_and_without_culling(const Scene& scene, bool layers = false) {
    RenderSettings on;
    on.width = scene.image.width;
    on.height = scene.image.height;
    on.samples_per_pixel = scene.image.samples_per_pixel;
    on.threads = 2;
    on.layers = layers;
    RenderSettings off = on;
    off.frustum_culling = false;
    return {render(scene, on), render(scene, off)};
}

TEST(FrustumCulling, ImagesAreTheSameWithAndWithoutIt) {
    const Scene scene = parse_scene(scene_text(), "beads.zs", ".");
    const auto [culled, traced] = render_with_and_without_culling(scene);
    ASSERT_EQ(culled.stats.partitions.empty(), false);  // the objects are partitioned: culling applies
    EXPECT_GT(culled.stats.hits, 1000u);                 // and much of the frame is surface
    EXPECT_EQ(culled.stats.hits, traced.stats.hits);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < culled.image.pixels.size(); ++i)
        if (!(culled.image.pixels[i] == traced.image.pixels[i])) ++differing;
    EXPECT_EQ(differing, 0u);
    // The culling did work: the rays spent fewer point evaluations.
    EXPECT_LT(culled.stats.counters.point_evaluations, traced.stats.counters.point_evaluations);
}

// Tiles whose rays all pass beside the scene's bounds are filled with the
// background without making their rays: the same pixels, layers and ray
// count as tracing every ray, with three samples a pixel. (The layers'
// no-hit values are also what a new image holds, so that part only shows
// that the fill writes nothing else there.)
TEST(FrustumCulling, TilesBesideTheSceneAreTheBackgroundAsTraced) {
    const Scene scene = parse_scene(R"(
image  { width 80  height 48  spp 3 }
camera { from (0, 0, -6)  at (0, 0, 0)  fov 40 }
background (0.1, 0.3, 0.7)
object "corner" { surface x^2 + y^2 + z^2 - 0.09  bounds box((-0.31, -0.31, -0.31), (0.31, 0.31, 0.31))
                  translate (1.6, 0.8, 0) }
)",
                                    "corner.zs", ".");
    const auto [culled, traced] = render_with_and_without_culling(scene, true);
    EXPECT_GT(culled.stats.hits, 20u);  // the sphere is in the picture
    EXPECT_EQ(culled.stats.hits, traced.stats.hits);
    EXPECT_EQ(culled.stats.camera_rays, traced.stats.camera_rays);
    EXPECT_EQ(culled.stats.camera_rays, 80u * 48u * 3u);
    std::size_t differing = 0, background = 0;
    for (std::size_t i = 0; i < culled.image.pixels.size(); ++i) {
        if (!(culled.image.pixels[i] == traced.image.pixels[i]) || !(culled.image.normals[i] == traced.image.normals[i]) ||
            culled.image.depth[i] != traced.image.depth[i])
            ++differing;
        if (std::isinf(culled.image.depth[i])) ++background;
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(background, culled.image.pixels.size() / 2);  // most of the frame is background
}

// A blob's camera rays meet its components by their tile's list: the same
// image as by its BVH, directly and through a turned instance, with two
// rays a pixel — to rounding (the components come in another order, so a
// segment's terms are summed in another).
TEST(FrustumCulling, ABlobsImageIsTheSameByItsTilesLists) {
    std::string components;
    for (int i = 0; i < 120; ++i) {
        const double a = 0.37 * i, r = 0.4 + 0.012 * i;
        components += "  component { center (" + std::to_string(r * std::cos(a)) + ", " + std::to_string(0.02 * i - 1.2) +
                      ", " + std::to_string(r * std::sin(a)) + ") radius " + std::to_string(0.35 + 0.1 * std::sin(1.7 * i)) + " }\n";
    }
    const std::string text = R"(
image  { width 64  height 48  spp 2 }
camera { from (0.4, 2.2, -6)  at (0, 0, 0)  fov 40 }
light  { from (-4, 6, -5) }
shape spiral {
  blob { kernel povray  threshold 0.5
)" + components + R"(  }
}
instance spiral { translate (-0.8, 0, 0) }
instance spiral { rotate (20, 40, 0)  translate (1.0, 0.2, 0.5) }
)";
    const Scene scene = parse_scene(text, "spiral.zs", ".");
    const auto [listed, walked] = render_with_and_without_culling(scene);
    EXPECT_GT(listed.stats.counters.blob_list_rays, listed.stats.camera_rays / 4);  // the lists served
    EXPECT_EQ(walked.stats.counters.blob_list_rays, 0u);
    EXPECT_GT(listed.stats.hits, 1000u);
    EXPECT_EQ(listed.stats.hits, walked.stats.hits);
    float largest = 0.0f;
    for (std::size_t i = 0; i < listed.image.pixels.size(); ++i) {
        const Vec3f d = listed.image.pixels[i] - walked.image.pixels[i];
        largest = std::max({largest, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    }
    EXPECT_LE(largest, 1e-4f);
}

// Polynomial surfaces answer the camera rays of tiles proven empty at once
// (accel/polynomial_tile_proof.hpp): the same image as tracing every ray,
// for a sheet seen through a gate and a turned torus in an instance.
TEST(FrustumCulling, APolynomialSurfacesImageIsTheSameWithTileProofs) {
    const Scene scene = parse_scene(R"(
image  { width 160  height 120 }
camera { from (0, 1.5, -9)  at (0, 0, 0)  fov 45 }
light  { from (-4, 6, -5) }
object "sheet" {
  surface (x^2 + y^2 - z^2 + 0.6)^2 - 3.2 * (x^2 + y^2) + 0.1
  bounds box((-6, -6, -6), (6, 6, 6))  open on  gate sphere((0, 0, 0), 3)  method polynomial
  rotate (70, 20, 0)  translate (-1.2, 0, 0)
}
object "torus" {
  surface (x^2 + y^2 + z^2 + 0.3)^2 - 1.6 * (x^2 + y^2)
  bounds box((-1.5, -1.5, -0.6), (1.5, 1.5, 0.6))  method polynomial
  rotate (60, 0, 30)  translate (2.2, 0.3, 0)
}
)",
                                    "quartics.zs", ".");
    const auto [proven, traced] = render_with_and_without_culling(scene);
    // The proofs served: rays of a proven tile, and whole rows of them left untraced.
    EXPECT_GT(proven.stats.counters.proven_tile_rays, 0u);
    EXPECT_GT(proven.stats.untraced_camera_rays, proven.stats.camera_rays / 10);
    EXPECT_EQ(traced.stats.counters.proven_tile_rays, 0u);
    EXPECT_EQ(traced.stats.untraced_camera_rays, 0u);
    EXPECT_GT(proven.stats.hits, 500u);
    EXPECT_EQ(proven.stats.hits, traced.stats.hits);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < proven.image.pixels.size(); ++i)
        if (!(proven.image.pixels[i] == traced.image.pixels[i])) ++differing;
    EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace zeroset
