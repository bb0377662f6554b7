// TapePruner: the "simplified tape" of DESIGN.md. Evaluating a tape with
// intervals over a box also tells, for every min and max, whether one side
// wins everywhere in the box. The pruned tape keeps only what can still
// matter there: a CSG model of thousands of clauses shrinks to the few
// near the box, and every later evaluation inside the box (points,
// gradients, sub-boxes) walks the short tape instead.
//
// Tapes to prune must use SlotLayout::OnePerValue; a pruned tape keeps its
// parent's slot numbering, so evaluators switch to it with rebind() and
// a pruned tape can be pruned again over a smaller box. Pruning reuses its
// buffers and the output tape's: after warm-up it does not allocate.
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/interval.hpp"

namespace zeroset {

class TapePruner {
public:
    /// Sized for `full` (SlotLayout::OnePerValue) and every tape pruned from it.
    explicit TapePruner(const Tape& full);

    /// Evaluates `source` (the full tape or one pruned from it) over the box
    /// and writes into `out` the clauses live there. Returns f over the box.
    Interval prune(const Tape& source, const Box3& box, Tape& out);

private:
    enum class Choice : std::uint8_t { Both, Left, Right };

    Interval evaluate(const Tape& source, const Box3& box);
    void keep_live_clauses(const Tape& source, Tape& out);
    [[nodiscard]] std::uint32_t resolve(std::uint32_t slot) const;

    std::vector<Interval> slots_;
    std::vector<Choice> choices_;          // per clause of the source tape
    std::vector<std::uint32_t> live_;      // slot is live when live_[slot] == epoch_
    std::vector<std::uint32_t> aliased_;   // slot is an alias when aliased_[slot] == epoch_
    std::vector<std::uint32_t> alias_of_;  // … of this slot
    std::uint32_t epoch_ = 0;
};

}  // namespace zeroset
