// Cone antialiasing against what it approximates: the disk's covered share
// against counting points of a fine grid, and whole images against a
// 256-sample render of the same scene — where stratified samples converge
// to the pixel's true mean. Shadows are off, since the cone blends only
// geometric edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "zeroset/render/cone_tracer.hpp"
#include "zeroset/render/renderer.hpp"

namespace zeroset {
namespace {

TEST(DiskCoverage, MatchesACountOfGridPoints) {
    constexpr int n = 2000;
    for (const double u : {-0.95, -0.6, -0.2, 0.0, 0.25, 0.5, 0.8, 0.97}) {
        long in_disk = 0, beyond = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double x = -1.0 + (i + 0.5) * 2.0 / n, y = -1.0 + (j + 0.5) * 2.0 / n;
                if (x * x + y * y > 1.0) continue;
                ++in_disk;
                beyond += x > u ? 1 : 0;
            }
        EXPECT_NEAR(disk_coverage(u), static_cast<double>(beyond) / static_cast<double>(in_disk), 2e-4) << u;
    }
    EXPECT_EQ(disk_coverage(0.0), 0.5);
    EXPECT_EQ(disk_coverage(1.0), 0.0);
    EXPECT_EQ(disk_coverage(3.0), 0.0);
    EXPECT_EQ(disk_coverage(-1.0), 1.0);
    EXPECT_NEAR(disk_coverage(0.4) + disk_coverage(-0.4), 1.0, 1e-15);
}

Expr ball(const Vec3d& c, double r) {
    return square(var_x() - c.x) + square(var_y() - c.y) + square(var_z() - c.z) - r * r;
}

SceneNodePtr object(const Expr& f, const Box3& box, const Vec3d& color, bool cut = false) {
    Object o;
    o.surface = f;
    o.bounds = Bounds::make_box(box);
    o.cut_by_bounds = cut;
    Material m;
    m.color = color;
    return make_object_node(o, "", m);
}

Scene base_scene() {
    Scene s;
    s.camera.from = {0, 1.5, -7};
    s.camera.at = {0, 0, 0};
    s.camera.fov_degrees = 40;
    s.lights.push_back({Light::Kind::Point, {-6, 8, -8}, {}, {1, 1, 1}, false});
    s.background = {0.05, 0.05, 0.3};
    s.nodes.push_back(object(var_y() + 0.95, {{-4, -1.1, -9}, {4, -0.9, 3}}, {0.8, 0.8, 0.7}, true));
    return s;
}

/// Smooth silhouettes only: a sphere and a tilted torus (placed by a
/// transform) over a slab floor whose bounds cut its far edge (its near one
/// is behind the camera).
Scene silhouettes_scene() {
    Scene s = base_scene();
    s.nodes.push_back(object(ball({-1.1, 0, 0}, 0.9), {{-2.1, -1, -1}, {-0.1, 1, 1}}, {0.9, 0.3, 0.2}));
    const Expr rho = sqrt(square(var_x()) + square(var_z())) - 0.7;
    auto torus = std::make_shared<SceneNode>(
        *object(square(rho) + square(var_y()) - 0.06, {{-1, -0.3, -1}, {1, 0.3, 1}}, {0.2, 0.7, 0.3}));
    torus->transform = Mat4::translate({1.3, 0, 0}) * Mat4::rotate_degrees({1, 0, 0}, 60);
    s.nodes.push_back(torus);
    return s;
}

/// A box with a ball taken out of it, turned: the cube's silhouettes come
/// from CSG and a transform, and it has creases — its edges between faces
/// seen from the front, the rim of the hollow — which no cone blends.
Scene creased_scene() {
    Scene s = base_scene();
    auto cut = std::make_shared<SceneNode>();
    cut->kind = SceneNode::Kind::Difference;
    const Expr cube = max(max(abs(var_x()), abs(var_y())), abs(var_z())) - 0.7;
    cut->children = {object(cube, {{-0.8, -0.8, -0.8}, {0.8, 0.8, 0.8}}, {0.2, 0.7, 0.3}),
                     object(ball({0, 0.35, -0.35}, 0.6), {{-0.7, -0.3, -1}, {0.7, 1, 0.3}}, {0.2, 0.7, 0.3})};
    cut->transform = Mat4::translate({0.3, -0.2, 0}) * Mat4::rotate_degrees({0, 1, 0}, 30);
    s.nodes.push_back(cut);
    return s;
}

Image render_with(const Scene& scene, int spp, bool cone, RenderStats* stats = nullptr) {
    RenderSettings settings;
    settings.width = 120;
    settings.height = 90;
    settings.samples_per_pixel = spp;
    settings.cone_antialiasing = cone;
    RenderResult result = render(scene, settings);
    if (stats) *stats = result.stats;
    return result.image;
}

double difference(const Image& a, const Image& b, int x, int y) {
    const Vec3f p = a.at(x, y), q = b.at(x, y);
    return std::max({std::abs(p.x - q.x), std::abs(p.y - q.y), std::abs(p.z - q.z)});
}

struct EdgeErrors {
    int edges = 0;              // pixels where one ray is far from the mean
    double one_ray = 0.0;       // their mean error with one ray
    double cone = 0.0;          // and with cone antialiasing
    int smooth = 0;             // pixels far from every edge
    int smooth_changed = 0;     // of which the cone changed
    std::uint64_t cone_edges = 0;
};

EdgeErrors measure(const Scene& scene) {
    RenderStats stats;
    const Image one = render_with(scene, 1, false), cone = render_with(scene, 1, true, &stats);
    const Image reference = render_with(scene, 256, false);
    EdgeErrors e;
    for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x) {
            const double off = difference(one, reference, x, y);
            if (off > 0.05) {
                ++e.edges;
                e.one_ray += off;
                e.cone += difference(cone, reference, x, y);
            } else if (off < 0.002) {
                ++e.smooth;
                e.smooth_changed += difference(cone, one, x, y) > 0.01 ? 1 : 0;
            }
        }
    e.one_ray /= std::max(e.edges, 1);
    e.cone /= std::max(e.edges, 1);
    e.cone_edges = stats.cone.edges;
    EXPECT_EQ(stats.camera_rays, 120u * 90u);
    std::printf("%d edge pixels: mean error one ray %.4f, cone %.4f; %d of %d smooth pixels changed\n", e.edges,
                e.one_ray, e.cone, e.smooth_changed, e.smooth);
    return e;
}

TEST(ConeAntialiasing, SilhouettesComeCloseToManySamplesAndTheRestIsUntouched) {
    const EdgeErrors e = measure(silhouettes_scene());
    ASSERT_GT(e.edges, 200);
    EXPECT_LT(e.cone, 0.2 * e.one_ray);
    EXPECT_LT(e.smooth_changed, e.smooth / 200);
    EXPECT_GT(e.cone_edges, static_cast<std::uint64_t>(e.edges / 2));
}

TEST(ConeAntialiasing, CsgSilhouettesAreBlendedButCreasesAreNot) {
    const EdgeErrors e = measure(creased_scene());
    ASSERT_GT(e.edges, 200);
    EXPECT_LT(e.cone, 0.6 * e.one_ray);
    EXPECT_GT(e.cone, 0.1 * e.one_ray);  // the creases stay as one ray sees them
    EXPECT_LT(e.smooth_changed, e.smooth / 200);
}

TEST(ConeAntialiasing, ScenesWithNothingToBlendRenderAsOneRaySeesThem) {
    // Only an unbounded plane (the cone marches inside bounded objects'
    // box), no objects at all, and a camera inside a ball.
    Scene plane = base_scene();
    plane.nodes.clear();
    Object ground;
    ground.surface = var_y() + 1.0;
    ground.bounds = Bounds::none();
    plane.nodes.push_back(make_object_node(ground));
    Scene empty = base_scene();
    empty.nodes.clear();
    Scene inside = silhouettes_scene();
    inside.camera.from = {-1.1, 0, 0};
    inside.camera.at = {-1.1, 0, 1};
    for (const Scene* scene : {&plane, &empty, &inside}) {
        const Image one = render_with(*scene, 1, false), cone = render_with(*scene, 1, true);
        double largest = 0.0;
        for (int y = 0; y < one.height; ++y)
            for (int x = 0; x < one.width; ++x) largest = std::max(largest, difference(one, cone, x, y));
        EXPECT_EQ(largest, 0.0);
    }
}

TEST(ConeAntialiasing, NeedsOneSamplePerPixel) {
    RenderSettings settings;
    settings.cone_antialiasing = true;
    settings.samples_per_pixel = 4;
    EXPECT_THROW(validate(settings), RenderError);
    settings.samples_per_pixel = 1;
    EXPECT_NO_THROW(validate(settings));
}

}  // namespace
}  // namespace zeroset
