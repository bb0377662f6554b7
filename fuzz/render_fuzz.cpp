// Fuzz target: parse a scene and render it at 8×6 on one thread. Every
// scene either renders (with finite pixels: the renderer refuses others) or
// stops with a SceneError or RenderError; anything else is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zeroset;
    const fuzz::ExpressionBudget budget(5'000);  // small tapes: preparing an object costs ≤ 491 552 interval evaluations
    try {
        const Scene scene = parse_scene(fuzz::as_text(data, size), "fuzz.zs", ".", fuzz::small_limits());
        RenderSettings settings;
        settings.width = 8;
        settings.height = 6;
        settings.threads = 1;
        settings.max_evaluations = 20'000;  // a costly scene stops in milliseconds, with a RenderError
        (void)render(scene, settings);
    } catch (const SceneError&) {
    } catch (const RenderError&) {
    } catch (const ExpressionTooLarge&) {
    }
    return 0;
}
