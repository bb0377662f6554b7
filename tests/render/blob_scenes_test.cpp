// The blob scenes of scenes/blobs/ rendered small: each one shows its
// object; the survey's figures written as blobs cover the pixels their
// expression versions cover; and a blob traced by a general method (its
// field as an expression) covers the pixels its own exact path does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "support/coverage.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

/// Which pixels show an object rather than the background.
std::vector<bool> coverage(const Scene& scene, int width, int height, std::optional<Method> method = {}) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.method = method;
    return test::coverage(scene, settings);
}

using test::covered;

double differing(const std::vector<bool>& a, const std::vector<bool>& b) {
    int n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return static_cast<double>(n) / static_cast<double>(a.size());
}

Scene scene_file(const std::string& path) { return load_scene(ZEROSET_SOURCE_DIR "/scenes/" + path); }

TEST(BlobScenes, EveryOneShowsItsBlob) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(ZEROSET_SOURCE_DIR "/scenes/blobs")) {
        const Scene scene = load_scene(entry.path());
        const double part = covered(coverage(scene, 96, 72));
        std::printf("%s: %.1f %% of the pixels covered\n", entry.path().filename().c_str(), 100.0 * part);
        EXPECT_GT(part, 0.05) << entry.path();
        EXPECT_LT(part, 1.0) << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 5);
}

TEST(BlobScenes, TheSurveysFiguresAsBlobsCoverWhatTheirExpressionsCover) {
    for (const auto& [blob, expression] : {std::pair{"blobs/figure1_blinn.zs", "hart1993/blinn_blobs.zs"},
                                           std::pair{"blobs/figure8_soft.zs", "hart1993/soft_objects.zs"}}) {
        // The expression by the general interval method: `auto` would trace it as a blob too.
        const std::vector<bool> a = coverage(scene_file(blob), 160, 120),
                                b = coverage(scene_file(expression), 160, 120, Method::Interval);
        EXPECT_GT(covered(a), 0.1) << blob;
        EXPECT_LE(differing(a, b), 0.001) << blob;
    }
}

TEST(BlobScenes, GeneralMethodsOnTheSameBlobCoverWhatItsOwnPathCovers) {
    // Soft objects, and spheres with cylinders (whose expression clamps the
    // nearest point of each segment).
    for (const auto& [file, width] : {std::pair{"blobs/figure8_soft.zs", 160}, std::pair{"blobs/ball_and_stick.zs", 80}}) {
        const Scene scene = scene_file(file);
        const int height = width * 3 / 4;
        const std::vector<bool> own = coverage(scene, width, height);
        for (const Method m : {Method::Interval, Method::Lg}) {
            const std::vector<bool> general = coverage(scene, width, height, m);
            EXPECT_LE(differing(own, general), 0.001) << file << ": " << method_name(m);
        }
    }
}

TEST(BlobScenes, ABlobBuiltInCppRendersAsItsSceneFileDoes) {
    // docs/blobs.md's example: Figure 8's soft objects without the scene language.
    std::vector<BlobComponent> parts(2);
    parts[0].center = {1.2, 0, 0};
    parts[1].center = {-1.2, 0, 0};
    for (auto& p : parts) p.radius = 2, p.strength = 2;
    Object soft;
    soft.blob = std::make_shared<const BlobModel>(BlobKernel::Soft, 1.0, parts);
    soft.bounds = Bounds::make_box(*soft.blob->solid_bounds(soft.blob_tolerance));
    Scene scene = scene_file("blobs/figure8_soft.zs");
    const std::vector<bool> from_file = coverage(scene, 160, 120);
    scene.nodes = {make_object_node(soft, "soft")};
    EXPECT_EQ(coverage(scene, 160, 120), from_file);
}

TEST(BlobScenes, ASumOfGaussiansIsTracedAsABlobWithinItsBounds) {
    // The survey's Figure 1 written as an expression is recognised; then
    // the same sum cut by its bounds on purpose, which the blob keeps.
    const std::string gaussians = "1 - exp(-((x - 1.2)^2 + y^2 + z^2 - 1)) - exp(-((x + 1.2)^2 + y^2 + z^2 - 1))";
    for (const char* bounds : {"box((-2.4, -1.2, -1.2), (2.4, 1.2, 1.2))", "box((-1.5, -0.6, -1.2), (2.4, 1.2, 1.2))  cut on"}) {
        const Scene scene = parse_scene("camera { from (0, 2.5, -9)  at (0, -0.2, 0)  fov 30 }\n"
                                        "object \"blobs\" { surface " + gaussians + "  bounds " + bounds + " }\n",
                                        "gaussians.zs", ".");
        RenderSettings settings;
        settings.width = 160;
        settings.height = 120;
        const RenderResult blob = render(scene, settings);
        EXPECT_NE(blob.stats.blobs.find("a sum of Gaussians, recognised"), std::string::npos) << blob.stats.blobs;
        settings.method = Method::Interval;
        const RenderResult general = render(scene, settings);
        EXPECT_TRUE(general.stats.blobs.empty()) << general.stats.blobs;
        // The same pixels, shaded alike (the cut faces included).
        int differ = 0;
        for (std::size_t i = 0; i < blob.image.pixels.size(); ++i) {
            const Vec3f d = blob.image.pixels[i] - general.image.pixels[i];
            differ += std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > 0.02f;
        }
        EXPECT_LE(differ, 20) << bounds;  // of 19 200: silhouettes may round either way
        EXPECT_GT(covered(test::coverage(scene, settings)), 0.05) << bounds;
    }
}

TEST(BlobScenes, ASumOfGaussiansTheBlobCannotTakeIsTracedAsWritten) {
    // No term adds to the field (f = 1 + e^(−r²) > 0: nothing to see): as an
    // expression, not an error.
    const Scene scene = parse_scene("object \"none\" { surface 1 + exp(-(x^2 + y^2 + z^2))  bounds box((-2, -2, -2), (2, 2, 2)) }\n"
                                    "object \"ball\" { surface x^2 + y^2 + z^2 - 0.25 }\n",
                                    "gaussians.zs", ".");
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    const RenderResult r = render(scene, settings);
    EXPECT_TRUE(r.stats.blobs.empty()) << r.stats.blobs;
    EXPECT_GT(covered(test::coverage(scene, settings)), 0.0);
}

}  // namespace
}  // namespace zeroset
