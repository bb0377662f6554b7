// TapePruner: the "simplified tape" of DESIGN.md. Evaluating a tape with
// intervals over a box also tells, for every min and max, whether one side
// wins everywhere in the box. The pruned tape keeps only what can still
// matter there: a CSG model of thousands of clauses shrinks to the few
// near the box, and every later evaluation inside the box (points,
// gradients, sub-boxes) walks the short tape instead.
//
// Pruning and slot allocation are one job: the pruned tape gets its own,
// compact slot numbering (live constants first, then working slots reused
// once dead), so a short tape is also short in slots and a batch of lanes
// over it stays in L1. The analysis follows values, not slots, so any tape
// can be pruned — the full tape or one already pruned, over a smaller box.
// Evaluators switch to a pruned tape with rebind(), which loads its
// constants. Pruning reuses its buffers and the output tape's: after
// warm-up it does not allocate.
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/interval.hpp"

namespace zeroset {

class TapePruner {
public:
    /// Sized for `full` and every tape pruned from it.
    explicit TapePruner(const Tape& full);

    /// Evaluates `source` (the full tape or one pruned from it) over the box
    /// and writes into `out` the clauses live there. Returns f over the box.
    Interval prune(const Tape& source, const Box3& box, Tape& out) {
        const Interval value = evaluate(source, box);
        simplify(out);
        return value;
    }

    /// prune() in two steps, for callers that may not need the pruned tape:
    /// f over the box, recording which side of each min and max wins there…
    Interval evaluate(const Tape& source, const Box3& box);
    /// … whether any min or max has a side that wins over the whole box (if
    /// none does, the pruned tape would be the source itself) …
    [[nodiscard]] bool any_choice() const { return choices_made_ > 0; }
    /// … and the tape pruned to the box of the last evaluate().
    void simplify(Tape& out);

private:
    enum class Choice : std::uint8_t { Both, Left, Right };

    void mark_live_values();
    void emit_live_clauses(Tape& out);
    [[nodiscard]] bool is_clause_value(std::uint32_t id) const { return id >= base_; }

    // A value's id is its slot for x, y, z and constants (never overwritten),
    // and base_ + i for the result of clause i.
    std::uint32_t base_;
    const Tape* source_ = nullptr;  // of the last evaluate()
    std::size_t choices_made_ = 0;
    std::vector<Interval> slots_;
    std::vector<std::uint32_t> value_in_slot_;  // during evaluate(): the id each slot holds
    std::vector<Choice> choices_;               // per clause of the source tape
    std::vector<std::uint32_t> operand_a_, operand_b_;  // per clause: its operands' ids, min/max resolved
    std::vector<std::uint32_t> equals_;         // per clause: the id its value equals (itself unless chosen)
    std::vector<std::uint32_t> live_;           // per id: live when live_[id] == epoch_
    std::vector<std::uint32_t> uses_;           // per live id: uses by live clauses still to emit
    std::vector<std::uint32_t> new_slot_;       // per live id: its slot in the pruned tape
    std::vector<std::uint32_t> free_slots_;
    std::uint32_t epoch_ = 0;
};

}  // namespace zeroset
