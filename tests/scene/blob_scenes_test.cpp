// Blobs in the scene language: what `blob { … }` reads, the errors it
// gives, and the survey's two-sphere example written as a Blinn blob and as
// soft objects, which must cross the survey's ray where the same fields
// written as expressions do (tests/trace/worked_example_test.cpp).
#include <memory>

#include "scene/scene_test_support.hpp"
#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {
namespace {

using test::error_of;
using test::parse;

const Ray survey_ray{{-4.905, -0.67, 0.364}, {0.981, 0.174, 0.0872}};

Scene scene_file(const std::string& path) { return load_scene(std::string(ZEROSET_SOURCE_DIR) + "/scenes/" + path); }

/// The t where the survey's ray crosses the object's surface, by its spans.
std::vector<double> crossings(const Primitive& p) {
    TraceScratch scratch(1);
    SpanList spans;
    p.spans(survey_ray, 0.0, 30.0, scratch, spans);
    std::vector<double> t;
    for (const InsideSpan& s : spans) {
        t.push_back(s.enter.t);
        t.push_back(s.exit.t);
    }
    return t;
}

void expect_same_crossings(const std::string& blob_scene, const std::string& expression_scene, std::size_t count) {
    const Scene blob = scene_file(blob_scene), expression = scene_file(expression_scene);
    const Object& b = placed_objects(blob).at(0).object();
    const Object& e = placed_objects(expression).at(0).object();
    ASSERT_TRUE(b.blob);
    const Blob primitive(BlobDescription{"blob", b.blob, no_material, 1e-12, 1});
    LeafDescription d;
    d.surface = e.surface;
    d.bounds = e.bounds;
    d.method = Method::Interval;
    const ImplicitLeaf leaf(0, d);
    const std::vector<double> mine = crossings(primitive), theirs = crossings(leaf);
    ASSERT_EQ(mine.size(), count);
    ASSERT_EQ(theirs.size(), count);
    for (std::size_t i = 0; i < count; ++i) EXPECT_NEAR(mine[i], theirs[i], 1e-9) << "root " << i;
}

TEST(BlobScenes, FigureOneAsABlinnBlobCrossesTheSurveysRayFourTimes) {
    expect_same_crossings("blobs/figure1_blinn.zs", "hart1993/blinn_blobs.zs", 4);
}

TEST(BlobScenes, SoftObjectsAsABlobCrossTheSurveysRayWhereTheExpressionDoes) {
    expect_same_crossings("blobs/figure8_soft.zs", "hart1993/soft_objects.zs", 4);
}

TEST(BlobScenes, ReadsKernelsComponentsAndTheirShapes) {
    const Scene scene = parse(R"(
        blob "b" {
          kernel metaball  threshold 0.4
          component { center (1, 2, 3)  radius 2  strength -0.5 }
          for i from 1 to 3 { component { center (i, 0, 0)  scale (1, 2, 1) } }
          translate (0, 1, 0)
        })");
    const PlacedObject placed = placed_objects(scene).at(0);
    const BlobModel& m = *placed.object().blob;
    EXPECT_EQ(m.kernel(), BlobKernel::Metaball);
    EXPECT_EQ(m.threshold(), 0.4);
    ASSERT_EQ(m.components().size(), 4u);
    EXPECT_EQ(m.components()[0].strength, -0.5);
    EXPECT_EQ(m.components()[3].center.x, 3.0);
    EXPECT_EQ(m.components()[3].shape, Mat4::scale({1, 2, 1}));
    EXPECT_EQ(placed.to_scene, Mat4::translate({0, 1, 0}));
    // Its bounds are its positive components' reach: the ellipsoids reach y = ±2.
    EXPECT_NEAR(placed.object().bounds.box.hi.y, 2.0, 1e-9);
    EXPECT_NEAR(placed.object().bounds.box.lo.x, 0.0, 1e-9);
    // A cylinder: its ends, and its bounds the spheres about them.
    const Scene tube = parse("blob { component { from (0, 0, 0) to (4, 0, 0) radius 0.5 } }");
    const PlacedObject t = placed_objects(tube).at(0);
    const BlobComponent& c = t.object().blob->components().at(0);
    ASSERT_TRUE(c.is_cylinder());
    EXPECT_EQ(c.center, (Vec3d{0, 0, 0}));
    EXPECT_EQ(*c.end, (Vec3d{4, 0, 0}));
    EXPECT_NEAR(t.object().bounds.box.lo.x, -0.5, 1e-9);
    EXPECT_NEAR(t.object().bounds.box.hi.x, 4.5, 1e-9);
    EXPECT_NEAR(t.object().bounds.box.hi.z, 0.5, 1e-9);
}

TEST(BlobScenes, BadBlobsGetClearErrors) {
    EXPECT_EQ(error_of("blob { kernel povray }"), "scene.zs:1:1: a blob needs at least one component");
    EXPECT_EQ(error_of("blob { kernel gauss component { } }"),
              "scene.zs:1:15: unknown kernel 'gauss' (expected blinn, metaball, soft or povray)");
    EXPECT_EQ(error_of("blob { component { radius 0 } }"), "scene.zs:1:27: the radius must be positive");
    EXPECT_EQ(error_of("blob { component { } kernel soft }"),
              "scene.zs:1:22: the kernel must come before the blob's components");
    EXPECT_EQ(error_of("blob { component { blobbiness -2 } }"),
              "scene.zs:1:20: blobbiness is a parameter of the blinn kernel only");
    EXPECT_EQ(error_of("blob { kernel blinn component { blobbiness 2 } }"),
              "scene.zs:1:44: the blobbiness must be negative (Blinn's B < 0)");
    EXPECT_EQ(error_of("blob { component { strength -1 } }"),
              "scene.zs:1:1: a blob needs a component of positive strength (its field never reaches the threshold)");
    EXPECT_EQ(error_of("blob { threshold 0 component { } }"), "scene.zs:1:18: the threshold must be positive");
    EXPECT_EQ(error_of("blob { component { } surface x }"),
              "scene.zs:1:22: expected a key (kernel, threshold, tolerance, quadratics, component, method, normals, "
              "partition or material), a transform, let, for or '}' but found 'surface'");
    EXPECT_EQ(error_of("blob { quadratics on component { } }"),
              "scene.zs:1:8: quadratics (the survey's approximation by quadratic pieces) is for the metaball kernel only");
    EXPECT_EQ(error_of("blob { quadratics on kernel metaball component { } }"), "");
    EXPECT_EQ(error_of("blob { component { center (1e308, 0, 0)  radius 1e308 } component { center (-1e308, 0, 0) } }"),
              "scene.zs:1:1: the blob's reach is wider than a double can measure");  // any order before the components
    EXPECT_EQ(error_of("blob { component { from (0, 0, 0) radius 2 } }"),
              "scene.zs:1:20: a cylinder component needs both ends: from (x, y, z) to (x, y, z)");
    EXPECT_EQ(error_of("blob { component { center (1, 0, 0) from (0, 0, 0) to (1, 0, 0) } }"),
              "scene.zs:1:20: a cylinder component has ends (from, to), not a center");
    EXPECT_EQ(error_of("blob { component { from (0, 0, 0) to (1, 0, 0) scale 2 } }"),
              "scene.zs:1:48: a cylinder component takes no transform: move its ends instead");
    EXPECT_EQ(error_of("blob { component { from (0, 0, 0) to (0, 0, 0) } }"),
              "scene.zs:1:35: the cylinder's ends must differ (a sphere has a center)");
    EXPECT_EQ(error_of("blob { component { from (0, 0, 0) to (1e-200, 0, 0) } }"),
              "scene.zs:1:35: the cylinder is too short to measure: the square of its length is beyond a double");
    EXPECT_EQ(error_of("blob { component { from (1e200, 0, 0) to (-1e200, 0, 0) } }"),
              "scene.zs:1:39: the cylinder is too long to measure: the square of its length is beyond a double");
    EXPECT_EQ(error_of("blob { kernel metaball quadratics on component { from (0, 0, 0) to (1, 0, 0) } }"),
              "scene.zs:1:24: quadratics (the survey's quadratic pieces) is for round components, not cylinders");
    EXPECT_EQ(error_of("blob { component { radius 1e-310 } }"),
              "scene.zs:1:1: blob: component 1: its radius and shape map it outside what a double holds (radius 1e-310)");
}

}  // namespace
}  // namespace zeroset
