// The guaranteed methods find the same first hit on every ray, so the same
// scene drawn with each is the same image: the same pixels covered, and the
// same colours but for the last bits of a root refined from different
// brackets. A method that lost a thin part, a graze or a chord (sphere
// tracing did, in ε-segments) shows here as a pixel of another object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

Image draw(const std::string& file, Method method) {
    RenderSettings settings;
    settings.width = 120;
    settings.height = 90;
    settings.method = method;
    return render(load_scene(ZEROSET_SOURCE_DIR "/scenes/" + file), settings).image;
}

class GuaranteedMethods : public ::testing::TestWithParam<const char*> {};

TEST_P(GuaranteedMethods, DrawTheSameImage) {
    const Image interval = draw(GetParam(), Method::Interval);
    for (const Method method : {Method::Sphere, Method::Lg}) {
        const Image other = draw(GetParam(), method);
        ASSERT_EQ(other.pixels.size(), interval.pixels.size());
        int differ = 0;
        float worst = 0.0f;
        for (std::size_t i = 0; i < interval.pixels.size(); ++i) {
            const Vec3f d = other.pixels[i] - interval.pixels[i];
            const float largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
            worst = std::max(worst, largest);
            differ += largest > 1e-4f;
        }
        std::printf("%s, %s against interval: %d pixels differ by more than 1e-4, the most by %g\n", GetParam(),
                    std::string(method_name(method)).c_str(), differ, static_cast<double>(worst));
        EXPECT_EQ(differ, 0) << GetParam() << " with " << method_name(method);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GuaranteedMethods,
                         ::testing::Values("csg/machined_part_function.zs", "deform/twisted_torus.zs",
                                           "hart1993/soft_objects.zs", "examples/csg.zs", "blends/pipe_junction.zs"));

}  // namespace
}  // namespace zeroset
