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
    /// … and the tape to walk in the box of the last evaluate(): `out`,
    /// filled with the pruned tape, or — when no min or max has a side that
    /// wins over the whole box, so pruning would keep everything — that
    /// evaluation's source itself, with `out` left as it was.
    const Tape& simplified(Tape& out) {
        if (choices_made_ == 0) return *source_;
        simplify(out);
        return out;
    }

private:
    enum class Choice : std::uint8_t { Both, Left, Right };

    /// Writes the tape pruned to the box of the last evaluate() into `out`.
    void simplify(Tape& out);

    /// The value `v` is over the box: the winner of a min or max that has one.
    [[nodiscard]] ValueId resolve(ValueId v) const {
        if ((v & clause_value) == 0) return v;
        const std::uint32_t j = v & ~clause_value;
        return choices_[j] == Choice::Both ? v : equals_[j];
    }
    /// The slot of `v` in the pruned tape while it is being built, given at
    /// its last use (the first seen walking backwards), encoded until the
    /// number of constants is known.
    std::uint32_t take_slot(ValueId v);
    [[nodiscard]] std::uint32_t final_slot(std::uint32_t encoded) const;
    [[nodiscard]] ValueId final_value(ValueId v) const;

    const Tape* source_ = nullptr;  // of the last evaluate()
    std::size_t choices_made_ = 0;
    std::vector<Interval> slots_;
    std::vector<Choice> choices_;     // per clause of the source tape
    std::vector<ValueId> equals_;     // per chosen min/max: the (resolved) value it equals
    // Per clause and per constant of the source, stamped with epoch_ once live.
    std::vector<std::uint32_t> clause_live_, constant_live_;
    std::vector<std::uint32_t> working_slot_;    // per live clause: its working slot
    std::vector<std::uint32_t> emitted_at_;      // per live clause: its position, counted from the end
    std::vector<std::uint32_t> constant_index_;  // per live constant: its place among the pruned tape's constants
    std::vector<std::uint32_t> free_slots_;
    std::vector<Clause> reversed_;  // the kept clauses, last first, slots still marked
    std::vector<ClauseOperands> reversed_operands_;
    std::uint32_t working_slots_ = 0, constants_ = 0, emitted_ = 0;
    std::uint32_t epoch_ = 0;
};

}  // namespace zeroset
