// Fuzz target: the POV-Ray importer. Any text either imports or is a
// SceneError (file:line:column); anything else escaping is a finding. Small
// loop and expression budgets keep each input fast; includes are searched
// only beside the input (no installed include folders are read).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "zeroset/pov/pov_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zeroset;
    const fuzz::ExpressionBudget budget(200'000);
    pov::PovOptions options;
    options.width = 64;
    options.height = 48;
    options.max_loop_iterations = 10'000;
    options.search_installed_includes = false;
    try {
        const pov::PovImport imported = pov::parse_pov_scene(fuzz::as_text(data, size), "fuzz.pov", ".", options);
        (void)placed_objects(imported.scene);
    } catch (const SceneError&) {
    } catch (const ExpressionTooLarge&) {
    }
    return 0;
}
