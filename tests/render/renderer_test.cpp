// End-to-end renderer tests on scenes built in C++: coverage, shading,
// determinism across thread counts, supersampling and error reporting.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "zeroset/render/renderer.hpp"

namespace zeroset {
namespace {

/// The message of the RenderError the render throws, or "" when it renders.
std::string render_error(const Scene& scene, const RenderSettings& settings) {
    try {
        render(scene, settings);
    } catch (const RenderError& e) {
        return e.what();
    }
    return "";
}

Expr sphere(const Vec3d& c, double r) {
    return square(var_x() - c.x) + square(var_y() - c.y) + square(var_z() - c.z) - r * r;
}

/// The survey's Figure 1: Blinn's blend of unit spheres at (±1.2, 0, 0), eq. 12.
Scene blinn_scene() {
    Scene s;
    s.camera.from = {0, 0, -9};
    s.camera.fov_degrees = 40;
    s.lights.push_back({Light::Kind::Point, {-10, 10, -10}, {}, {1, 1, 1}, true});
    Object o;
    o.surface = Expr(1.0) - exp(-sphere({1.2, 0, 0}, 1)) - exp(-sphere({-1.2, 0, 0}, 1));
    o.bounds = Bounds::make_box({{-3.5, -2.5, -2.5}, {3.5, 2.5, 2.5}});
    Material red;
    red.color = {0.8, 0.3, 0.2};
    s.nodes.push_back(make_object_node(o, "blobs", red));
    return s;
}

bool is_background(const Image& image, int x, int y, const Vec3d& background) {
    const Vec3f p = image.at(x, y);
    return std::abs(p.x - background.x) < 1e-6 && std::abs(p.y - background.y) < 1e-6 &&
           std::abs(p.z - background.z) < 1e-6;
}

double coverage(const Image& image, const Vec3d& background) {
    int covered = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) covered += is_background(image, x, y, background) ? 0 : 1;
    return static_cast<double>(covered) / (image.width * image.height);
}

RenderSettings small(int threads = 2, int spp = 1) {
    RenderSettings s;
    s.width = 80;
    s.height = 60;
    s.threads = threads;
    s.samples_per_pixel = spp;
    return s;
}

TEST(Renderer, BlinnBlobsCoverTheExpectedPartOfTheFrame) {
    const Scene scene = blinn_scene();
    const RenderResult r = render(scene, small());
    // The pair spans about 4.4 × 2 units of the 6.55 × 4.9 view at distance 9
    // (40° field of view): a bit under a quarter of its bounding rectangle's share.
    const double c = coverage(r.image, scene.background);
    EXPECT_GT(c, 0.09);
    EXPECT_LT(c, 0.20);
    EXPECT_FALSE(is_background(r.image, 40, 30, scene.background));  // the neck between the blobs
    EXPECT_FALSE(is_background(r.image, 26, 30, scene.background));  // left blob
    EXPECT_FALSE(is_background(r.image, 54, 30, scene.background));  // right blob
    EXPECT_TRUE(is_background(r.image, 2, 2, scene.background));
    EXPECT_TRUE(is_background(r.image, 40, 5, scene.background));    // above the neck
    EXPECT_EQ(r.stats.camera_rays, 80u * 60u);
    EXPECT_GT(r.stats.hits, 0u);
    EXPECT_GT(r.stats.counters.point_evaluations, r.stats.camera_rays);
}

TEST(Renderer, LightFacingSideIsBrighterThanTheShadowSide) {
    const Scene scene = blinn_scene();  // light up-left-front
    const RenderResult r = render(scene, small());
    const Vec3f upper_left = r.image.at(22, 25), lower_right = r.image.at(58, 36);
    EXPECT_GT(upper_left.x, 2.0f * lower_right.x);
}

TEST(Renderer, ImageDoesNotDependOnThreadCount) {
    const Scene scene = blinn_scene();
    const RenderResult one = render(scene, small(1, 3));
    const RenderResult two = render(scene, small(2, 3));
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    for (std::size_t i = 0; i < one.image.pixels.size(); ++i) ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << i;
    EXPECT_EQ(one.stats.threads, 1);
    EXPECT_EQ(two.stats.threads, 2);
}

TEST(Renderer, DepthAndNormalLayersDescribeTheNearestHit) {
    Scene scene;
    scene.camera.from = {0, 0, -5};
    scene.camera.fov_degrees = 40;
    Object o;
    o.surface = sphere({0, 0, 0}, 1);
    o.bounds = Bounds::make_box({{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}});
    scene.nodes.push_back(make_object_node(o, "ball", Material{}));
    RenderSettings settings = small();
    EXPECT_FALSE(render(scene, settings).image.has_layers());  // only on request

    settings.width = settings.height = 33;  // odd: the middle pixel's centre is on the axis
    settings.layers = true;
    const Image image = render(scene, settings).image;
    ASSERT_TRUE(image.has_layers());
    const std::size_t middle = 16 * 33 + 16;
    EXPECT_NEAR(image.depth[middle], 4.0f, 1e-5f);  // the eye is 5 from the centre, the radius is 1
    EXPECT_NEAR(image.normals[middle].z, -1.0f, 1e-5f);
    int hits = 0;
    for (std::size_t i = 0; i < image.depth.size(); ++i) {
        const bool hit = !is_background(image, static_cast<int>(i % 33), static_cast<int>(i / 33), scene.background);
        ASSERT_EQ(std::isfinite(image.depth[i]), hit) << i;
        const Vec3f n = image.normals[i];
        const float n2 = n.x * n.x + n.y * n.y + n.z * n.z;
        if (!hit) {
            ASSERT_EQ(n2, 0.0f) << i;
            continue;
        }
        ++hits;
        ASSERT_NEAR(n2, 1.0f, 1e-5f) << i;
        ASSERT_LT(n.z, 0.0f) << i;                                  // facing the eye
        ASSERT_GE(image.depth[i], 4.0f - 1e-5f) << i;               // nothing nearer than the front pole
        ASSERT_LE(image.depth[i], std::sqrt(24.0f) + 1e-4f) << i;   // nor farther than the silhouette
    }
    EXPECT_GT(hits, 100);
}

TEST(Renderer, SupersamplingSoftensEdges) {
    const Scene scene = blinn_scene();
    const RenderResult r = render(scene, small(2, 16));
    EXPECT_EQ(r.stats.camera_rays, 80u * 60u * 16u);
    // Some edge pixel must be a blend: neither background nor as bright as a full hit.
    int blended = 0;
    for (int x = 0; x < 80; ++x) {
        const Vec3f p = r.image.at(x, 30);
        if (p.x > scene.background.x + 0.01 && std::abs(p.x - r.image.at(40, 30).x) > 0.01) ++blended;
    }
    EXPECT_GT(blended, 0);
}

TEST(Renderer, ShadowsDarkenTheFloorUnderTheBlob) {
    Scene scene;
    scene.camera.from = {0, 3, -8};
    scene.camera.at = {0, -1, 0};
    scene.lights.push_back({Light::Kind::Directional, {}, {0, -1, 0}, {1, 1, 1}, true});
    Object ball;
    ball.surface = sphere({0, 0, 0}, 1);
    ball.bounds = Bounds::make_sphere({0, 0, 0}, 1.01);
    Object floor;
    floor.surface = var_y() + 1.5;
    floor.bounds = Bounds::make_box({{-20, -2, -20}, {20, -1, 20}});
    scene.nodes = {make_object_node(ball), make_object_node(floor)};
    const RenderResult lit = render(scene, small());
    scene.lights[0].casts_shadows = false;
    const RenderResult unshadowed = render(scene, small());
    // Find the floor directly below the ball: project (0, -1.5, 0) by scanning
    // for the pixel whose value changes between the two renders.
    int darker = 0;
    for (std::size_t i = 0; i < lit.image.pixels.size(); ++i)
        if (lit.image.pixels[i].x + 0.1f < unshadowed.image.pixels[i].x) ++darker;
    EXPECT_GT(darker, 20);
    EXPECT_GT(lit.stats.shadow_rays, 0u);
}

TEST(Renderer, SphereSdfWithUnboundedGradientNearTheCentreStillRenders) {
    // |∇| of sqrt(x²+y²+z²) is 1, but its interval enclosure over a box around
    // the origin is unbounded: the tracer must split segments, not give up.
    Scene scene;
    scene.camera.from = {0, 0, -4};
    Object o;
    o.surface = sqrt(square(var_x()) + square(var_y()) + square(var_z())) - 1.0;
    o.bounds = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
    scene.nodes.push_back(make_object_node(o));
    const RenderResult r = render(scene, small());
    const double expected = M_PI * std::pow(std::tan(std::asin(0.25)) / std::tan(20.0 * M_PI / 180.0), 2) *
                            (60.0 * 60.0) / (4.0 * 80.0 * 60.0);
    EXPECT_NEAR(coverage(r.image, scene.background), expected, 0.02);
}

TEST(Renderer, NanSurfaceIsAnErrorNamingTheObject) {
    Scene scene;
    Object o;
    o.surface = sqrt(var_x()) + square(var_y()) + square(var_z()) - 1.0;  // NaN for x < 0
    o.bounds = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
    scene.nodes.push_back(make_object_node(o, "bad"));
    const std::string error = render_error(scene, small());
    EXPECT_NE(error.find("'bad'"), std::string::npos) << error;
    EXPECT_NE(error.find("NaN"), std::string::npos) << error;
}

TEST(Renderer, RejectsImpossibleSettings) {
    const Scene scene = blinn_scene();
    RenderSettings s = small();
    s.width = 0;
    EXPECT_THROW(render(scene, s), RenderError);
    s = small();
    s.height = -5;
    EXPECT_THROW(render(scene, s), RenderError);
    s = small();
    s.samples_per_pixel = 0;
    EXPECT_THROW(render(scene, s), RenderError);
    s = small();
    s.width = 100000;
    EXPECT_THROW(render(scene, s), RenderError);
}

TEST(Renderer, RejectsDegenerateCamera) {
    Scene scene = blinn_scene();
    scene.camera.up = {0, 0, 1};  // parallel to the view direction
    EXPECT_THROW(render(scene, small()), RenderError);
    scene = blinn_scene();
    scene.camera.at = scene.camera.from;
    EXPECT_THROW(render(scene, small()), RenderError);
}

TEST(Renderer, SceneWithoutLightsGetsAHeadlight) {
    Scene scene = blinn_scene();
    scene.lights.clear();
    const RenderResult r = render(scene, small());
    EXPECT_GT(r.image.at(40, 30).x, 0.3f);
}

TEST(Renderer, ForwardDifferenceNormalsMatchAnalyticOnes) {
    Scene scene = blinn_scene();
    const RenderResult analytic = render(scene, small());
    RenderSettings fd_settings = small();
    fd_settings.normals = NormalMode::ForwardDifference;
    const RenderResult fd = render(scene, fd_settings);
    double worst = 0.0;
    for (std::size_t i = 0; i < analytic.image.pixels.size(); ++i)
        worst = std::max(worst, static_cast<double>(std::abs(analytic.image.pixels[i].x - fd.image.pixels[i].x)));
    EXPECT_LT(worst, 0.01);
}


TEST(Renderer, GuaranteedMethodsHitTheSamePixels) {
    Scene scene = blinn_scene();
    std::vector<RenderResult> results;
    for (const Method m : {Method::Interval, Method::Lg, Method::Sphere}) {
        RenderSettings s = small();
        s.method = m;
        results.push_back(render(scene, s));
    }
    for (std::size_t i = 1; i < results.size(); ++i) {
        EXPECT_EQ(results[i].stats.hits, results[0].stats.hits) << i;
        for (std::size_t p = 0; p < results[0].image.pixels.size(); ++p)
            ASSERT_NEAR(results[i].image.pixels[p].x, results[0].image.pixels[p].x, 1e-3) << "method " << i << " pixel " << p;
    }
}


// Bounds a double holds, moved by a transform past what it holds, are an
// error naming the node — not spans running to ∞ and NaN points.
TEST(Renderer, TransformedBoundsMustStayWithinDoublePrecision) {
    const auto scene_with_scale = [](double factor) {
        Scene scene;
        Object o;
        o.surface = sin(var_x()) + sin(var_y()) + sin(var_z());  // everywhere: the bounds stay as given
        o.bounds = Bounds::make_box({{-1e300, -1e300, -1e300}, {1e300, 1e300, 1e300}});
        auto node = std::make_shared<SceneNode>();
        node->kind = SceneNode::Kind::Object;
        node->name = "huge";
        node->object = o;
        node->transform = Mat4::scale({factor, factor, factor});
        scene.nodes.push_back(node);
        return scene;
    };
    EXPECT_NO_THROW(render(scene_with_scale(10.0), small()));
    // The most stretched map the parser accepts still renders a polynomial
    // surface under auto (the polynomial method: powers of the moved direction).
    Scene flat;
    Object ball;
    ball.surface = square(var_x()) + square(var_y()) + square(var_z()) - 1.0;
    ball.bounds = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
    auto squashed = std::make_shared<SceneNode>();
    squashed->kind = SceneNode::Kind::Object;
    squashed->object = ball;
    squashed->transform = Mat4::scale({1e-100, 1, 1e100});
    flat.nodes.push_back(squashed);
    EXPECT_EQ(render_error(flat, small()), "");
    EXPECT_EQ(render_error(scene_with_scale(1e10), small()),
              "object 'huge': its transforms move its bounds past what a double can hold (the diagonal of their box "
              "overflows); keep them within about ±5e307");
}

TEST(Renderer, OnlyAPlaneMayGoWithoutBounds) {
    Scene scene;
    Object o;
    o.surface = square(var_x()) + square(var_y()) + square(var_z()) - 1.0;
    o.bounds = Bounds::none();
    scene.nodes.push_back(make_object_node(o, "ball"));
    EXPECT_EQ(render_error(scene, small()), "object 'ball': an object without bounds must be a plane: its surface "
                                            "must be of degree 1 in x, y and z (give it bounds otherwise)");
}


// A surface that is NaN where rays look is an error under every method —
// the polynomial method too, whose F(t) then has NaN coefficients.
TEST(Renderer, NanSurfaceIsAnErrorUnderEveryMethod) {
    const Expr ball = square(var_x()) + square(var_y()) + square(var_z()) - 1.0;
    const Expr nan = Expr(0.0) / Expr(0.0);
    struct Case {
        Expr f;
        bool polynomial;
    };
    for (const Case& c : {Case{ball + nan, true}, Case{nan * var_x(), true}, Case{sqrt(var_x()) + ball, false}}) {
        for (const Method m : {Method::Auto, Method::Polynomial, Method::Interval, Method::Lg, Method::Sphere}) {
            if (m == Method::Polynomial && !c.polynomial) continue;
            // Partitioned too: cells where f is NaN throughout are kept, so rays still meet it.
            const bool can_partition = m == Method::Interval || m == Method::Lg || m == Method::Sphere;
            for (const Partition p : {Partition::None, Partition::Lipschitz}) {
                if (p == Partition::Lipschitz && !can_partition) continue;
                Scene scene;
                Object o;
                o.surface = c.f;
                o.bounds = Bounds::make_box({{-2, -2, -2}, {2, 2, 2}});
                o.method = m;
                o.partition = p;
                scene.nodes.push_back(make_object_node(o, "bad"));
                const std::string error = render_error(scene, small());
                EXPECT_NE(error.find("NaN"), std::string::npos) << c.f.to_string() << " with " << method_name(m)
                                                                << ", partition " << partition_name(p) << ": " << error;
            }
        }
    }
}


TEST(Renderer, AColourPastTheLargestFloatIsAnError) {
    Scene scene = blinn_scene();
    scene.lights[0].color = {1e300, 1e300, 1e300};
    const std::string error = render_error(scene, small());
    EXPECT_NE(error.find("has no finite colour"), std::string::npos) << error;
}


TEST(Renderer, AnImageTooLargeForMemoryIsRefusedBeforeAnyAllocation) {
    RenderSettings settings;
    settings.width = 65536;
    settings.height = 65536;
    try {
        validate(settings);
        FAIL() << "expected a RenderError";
    } catch (const RenderError& e) {
        EXPECT_EQ(std::string(e.what()), "65536x65536 is 4294967296 pixels, which would take 60 GiB; at most "
                                         "268435456 pixels (e.g. 16384x16384) are rendered");
    }
    settings.width = settings.height = 16384;  // 2^28, the limit
    EXPECT_NO_THROW(validate(settings));
    settings.height = 16385;
    EXPECT_THROW(validate(settings), RenderError);
}

TEST(Renderer, ALightAtTheHitPointLightsNothingThere) {
    // The camera sits on the plane x = 0, inside its half-space, where the
    // default light is too: no direction to the light, no NaN.
    Scene scene;
    Object o;
    o.surface = var_x();
    o.bounds = Bounds::make_box({{-1, -1, -1}, {1, 1, 1}});
    scene.camera.from = {0, 0, -0.5};
    scene.nodes.push_back(make_object_node(o));
    EXPECT_NO_THROW(render(scene, small()));
}


// The render-wide evaluation budget: a render that needs exactly the budget
// finishes; one evaluation less stops it with an error naming the option.
TEST(Renderer, TheEvaluationBudgetStopsARenderJustPastIt) {
    const Scene scene = blinn_scene();
    RenderSettings settings = small();
    settings.threads = 1;
    const std::uint64_t needed = render(scene, settings).stats.counters.evaluations();
    ASSERT_GT(needed, 100U);
    settings.max_evaluations = needed;
    EXPECT_EQ(render(scene, settings).stats.counters.evaluations(), needed);
    settings.max_evaluations = needed - 1;
    const std::string error = render_error(scene, settings);
    EXPECT_NE(error.find("--max-evaluations"), std::string::npos) << error;
    EXPECT_EQ(error.find("per camera ray"), std::string::npos) << "a budget given is not the default: " << error;
    settings.max_evaluations = 0;
    EXPECT_THROW(render(scene, settings), RenderError);
    // With two threads each spends its share of what is left.
    settings.threads = 2;
    settings.max_evaluations = needed / 4;
    EXPECT_NE(render_error(scene, settings).find("--max-evaluations"), std::string::npos);
    settings.max_evaluations = needed * 4;
    EXPECT_EQ(render_error(scene, settings), "");
}

TEST(Renderer, TheDefaultEvaluationBudgetGrowsWithTheRays) {
    RenderSettings settings;
    settings.width = 16;
    settings.height = 12;
    EXPECT_EQ(default_evaluation_budget(settings), least_evaluation_budget);
    settings.width = 640;
    settings.height = 480;
    settings.samples_per_pixel = 4;
    EXPECT_EQ(default_evaluation_budget(settings), 640ULL * 480 * 4 * evaluations_per_camera_ray);
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

// The default scene's floor alone: a plane in a thin box, lit by a point
// light, with nothing to cast a shadow. Shadows on must change no pixel. When
// shrinking the bounds left the box's top face on the plane, rays entering
// there started inside by rounding and the floor was speckled with false
// shadows and bounds-face normals (one pixel in eight).
TEST(Renderer, APlaneInAThinBoxShadowsNothing) {
    const auto floor_scene = [](bool shadows) {
        Scene s;
        s.camera.from = {0, 2.5, -9};
        s.camera.at = {0, -0.2, 0};
        s.camera.fov_degrees = 30;
        s.lights.push_back({Light::Kind::Point, {-10, 10, -10}, {}, {1, 1, 1}, shadows});
        Object floor;
        floor.surface = var_y() + 1.3;
        floor.bounds = Bounds::make_box({{-12, -1.4, -6}, {12, -1.2, 14}});
        s.nodes.push_back(make_object_node(floor, "floor"));
        return s;
    };
    const RenderResult lit = render(floor_scene(true), small());
    const RenderResult unshadowed = render(floor_scene(false), small());
    ASSERT_GT(lit.stats.hits, 100U);
    int differing = 0;
    for (std::size_t i = 0; i < lit.image.pixels.size(); ++i) {
        const Vec3f a = lit.image.pixels[i], b = unshadowed.image.pixels[i];
        differing += (a.x != b.x || a.y != b.y || a.z != b.z) ? 1 : 0;
    }
    EXPECT_EQ(differing, 0) << "of " << lit.stats.hits << " floor pixels";
}

}  // namespace
}  // namespace zeroset
