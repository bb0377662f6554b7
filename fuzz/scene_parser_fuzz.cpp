// Fuzz target: the scene language. Any text either parses or is a
// SceneError (file:line:column); anything else escaping is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "zeroset/scene/load_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zeroset;
    const fuzz::ExpressionBudget budget(200'000);
    try {
        const Scene scene = parse_scene(fuzz::as_text(data, size), "fuzz.zs", ".", fuzz::small_limits());
        (void)placed_objects(scene);
    } catch (const SceneError&) {
    }
    return 0;
}
