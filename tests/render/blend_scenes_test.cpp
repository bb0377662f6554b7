// The filleted pipe junction of scenes/blends/ (Hoffman and Hopcroft's
// algebraic blends, survey §3.3) traced by two different tracers: as the
// scene has it — object CSG of polynomial objects, each traced by its exact
// ray polynomial and the polynomial method's guarded solver — and with each
// fillet written as one expression max(blend, g − a, h − b) traced by the
// interval method. Every camera ray of a small image must find the same
// first hit with the same normal, and every hit on a fillet must lie on the
// parabola √(g/a) + √(h/b) = 1 of the potential method, which is written
// here apart from algebraic_blend's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/cli_test.hpp"
#include "zeroset/render/camera_rays.hpp"
#include "zeroset/render/prepared_scene.hpp"
#include "zeroset/render/scene_tracer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

const std::string scene_file = ZEROSET_SOURCE_DIR "/scenes/blends/pipe_junction.zs";

/// The scene's text with its fillet shape's body replaced by `body`.
std::string with_fillet_body(const std::string& body) {
    std::string text = test::read_text(scene_file);
    const std::size_t begin = text.find("  intersection {\n    object { cut on surface algebraic_blend");
    const std::size_t end = text.find("  }\n}\n", begin);
    EXPECT_NE(begin, std::string::npos);
    EXPECT_NE(end, std::string::npos);
    if (begin == std::string::npos || end == std::string::npos) return text;
    return text.replace(begin, end + 4 - begin, body);
}

TEST(BlendScenes, PolynomialCsgAndIntervalExpressionFindTheSameHits) {
    const Scene polynomial = load_scene(scene_file);
    const Scene interval = parse_scene(
        with_fillet_body("  object { cut on surface max(algebraic_blend(g, h, a, b), g - a, h - b)  bounds box(lo, hi)"
                         "  method interval }\n"),
        "pipe_junction_interval.zs", ZEROSET_SOURCE_DIR "/scenes/blends");
    const PreparedScene prepared_polynomial(polynomial), prepared_interval(interval);
    SceneTracer exact(prepared_polynomial), reference(prepared_interval);

    const int width = 160, height = 120;
    const CameraRays camera(polynomial.camera, width, height);
    int hits = 0, fillet_hits = 0, disagree = 0;
    double worst = 0.0, worst_bend = 0.0, worst_parabola = 0.0;
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const Ray ray = camera.ray(px, py, 0.5, 0.5);
            const auto a = exact.closest_hit(ray, INFINITY);
            const auto b = reference.closest_hit(ray, INFINITY);
            if (a.has_value() != b.has_value()) {
                ++disagree;
                continue;
            }
            if (!a) continue;
            ++hits;
            const double dt = std::abs(a->t - b->t);
            worst = std::max(worst, dt);
            const double bend = 1.0 - dot(a->normal, b->normal);
            worst_bend = std::max(worst_bend, bend);
            if (dt > 1e-9 * a->t || bend > 1e-9) ++disagree;
            // On a fillet: outside both solids it blends (post g, plate y, pipe h).
            const Vec3d p = a->point;
            const double post = p.x * p.x + p.z * p.z - 0.25, pipe = square(p.y - 1.2) + p.z * p.z - 0.09;
            const bool foot = post > 1e-6 && post < 0.36 && p.y > 1e-6 && p.y < 0.3;
            const bool joint = post > 1e-6 && post < 0.2 && pipe > 1e-6 && pipe < 0.12;
            if (!foot && !joint) continue;
            ++fillet_hits;
            const double parabola = foot ? std::sqrt(post / 0.36) + std::sqrt(p.y / 0.3)
                                         : std::sqrt(post / 0.2) + std::sqrt(pipe / 0.12);
            worst_parabola = std::max(worst_parabola, std::abs(parabola - 1.0));
        }
    }
    std::printf("pipe junction %dx%d: %d hits, %d on fillets, %d disagree, largest |dt| %.3g, largest "
                "1 - cos between normals %.3g, largest |sqrt(g/a) + sqrt(h/b) - 1| on fillets %.3g\n",
                width, height, hits, fillet_hits, disagree, worst, worst_bend, worst_parabola);
    EXPECT_GT(fillet_hits, hits / 20);  // about 9 % of the hits are on the fillets
    EXPECT_EQ(disagree, 0);
    EXPECT_LT(worst_parabola, 1e-9);
    EXPECT_EQ(exact.counters().interval_evaluations, 0u);  // the exact path is all polynomial
    EXPECT_GT(reference.counters().interval_evaluations, 0u);
    EXPECT_EQ(reference.counters().failed_queries, 0u);
}

}  // namespace
}  // namespace zeroset
