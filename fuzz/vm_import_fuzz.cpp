// Fuzz target: fidget's .vm format. Any text either imports — and then
// becomes a tape that evaluates at a point, over a box, and sliced at 32×32
// (interval culling, tape pruning, batch lanes) — or is a VmImportError
// naming its line and column.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz_support.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/vm_import.hpp"
#include "zeroset/render/slice.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zeroset;
    const fuzz::ExpressionBudget budget(200'000);
    std::istringstream in{std::string(fuzz::as_text(data, size))};
    try {
        const Expr f = import_vm(in);
        const Tape tape(f);
        Evaluator<double> eval(tape);
        (void)eval(0.1, 0.2, 0.3);
        Evaluator<Interval> box(tape);
        (void)evaluate_box(box, {-1, -1, -1}, {1, 1, 1});
        SliceSettings settings;
        settings.size = 32;
        settings.threads = 1;
        (void)slice(tape, settings);
    } catch (const VmImportError&) {
    } catch (const ExpressionTooLarge&) {
    }
    return 0;
}
