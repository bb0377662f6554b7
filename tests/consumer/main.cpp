// A user's program: a scene built in code from an expression parsed in the
// scene language, rendered through the public header, with an EXR written.
// It fails unless the sphere covers about the share of the frame it should.
#include <zeroset/zeroset.hpp>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: consumer OUT.exr\n", stderr);
        return 2;
    }
    zeroset::Scene scene;
    zeroset::Object ball;
    ball.surface = zeroset::evaluate_expression_text("sd_sphere(1)", {}, "<consumer>", ".").number();
    ball.bounds = zeroset::Bounds::make_sphere({0, 0, 0}, 1.5);
    scene.nodes.push_back(zeroset::make_object_node(ball, "ball"));
    zeroset::RenderSettings settings;
    settings.width = settings.height = 64;
    settings.layers = true;
    const zeroset::RenderResult result = zeroset::render(scene, settings);
    zeroset::write_image(result.image, argv[1]);
    int hits = 0;
    for (const float depth : result.image.depth) hits += std::isfinite(depth) ? 1 : 0;
    // The default camera is 5 from the centre with a 40° view: the ball's
    // silhouette has a radius of 64/2 · tan(asin(1/5)) / tan(20°) ≈ 17.9 pixels.
    const double expected = 3.14159265 * 17.9 * 17.9;
    std::printf("consumer: %d of %d pixels hit (expected about %.0f)\n", hits, 64 * 64, expected);
    return std::abs(hits - expected) < 0.05 * expected ? 0 : 1;
}
