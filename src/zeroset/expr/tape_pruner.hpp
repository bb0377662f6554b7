// TapePruner: the "simplified tape" of DESIGN.md. Evaluating a tape with
// intervals over a box also tells, for every min and max, whether one side
// wins everywhere in the box. The pruned tape keeps only what can still
// matter there: a CSG model of thousands of clauses shrinks to the few
// near the box, and every later evaluation inside the box (points,
// gradients, sub-boxes) walks the short tape instead.
//
// Pruning and slot allocation are one job: the pruned tape gets its own,
// compact slot numbering (each live constant a slot of its own, working
// slots reused once dead), so a short tape is also short in slots and a
// batch of lanes over it stays in L1. The analysis follows values, not
// slots — which value each slot holds is tracked as the tape is walked —
// so any tape can be pruned: the full tape or one already pruned, over a
// smaller box.
// Evaluators switch to a pruned tape with rebind(), which loads its
// constants. Pruning reuses its buffers and the output tape's: after
// warm-up it does not allocate.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/interval.hpp"
#include "zeroset/math/interval_lanes.hpp"

namespace zeroset {

class TapePruner {
public:
    /// How many boxes one walk of the lanes evaluate() takes.
    static constexpr int lanes = IntervalLanes::count;

    /// Sized for `full` and every tape pruned from it.
    explicit TapePruner(const Tape& full);

    /// Evaluates `source` (the full tape or one pruned from it) over the box
    /// and writes into `out` the clauses live there. Returns f over the box.
    Interval prune(const Tape& source, const Box3& box, Tape& out) {
        const Interval value = evaluate(source, box);
        simplify(out, 0);
        return value;
    }

    /// prune() in two steps, for callers that may not need the pruned tape:
    /// f over the box, recording which side of each min and max wins there…
    Interval evaluate(const Tape& source, const Box3& box);
    /// … or over four boxes in one walk, lane k for boxes[k] (the same
    /// bits as four calls of the one-box evaluate()) …
    IntervalLanes evaluate(const Tape& source, std::span<const Box3, lanes> boxes);

    /// … and the tape to walk in box `lane` of the last evaluate(): `out`,
    /// filled with the pruned tape, or — when no min or max has a side that
    /// wins over the whole box, so pruning would keep everything — that
    /// evaluation's source itself, with `out` left as it was.
    const Tape& simplified(Tape& out, int lane = 0) {
        if (choices_made_[lane] == 0) return *source_;
        simplify(out, lane);
        return out;
    }

private:
    /// Which value a clause's operand is, whatever slot holds it: x, y, z or
    /// a constant by its slot, or the result of a clause of the walked tape
    /// by the clause's index with `clause_value` set. Slots are reused; these
    /// ids are not, which is what following values needs.
    using ValueId = std::uint32_t;
    static constexpr ValueId clause_value = ValueId{1} << 31;
    /// A value as each lane's box sees it: a min or max with a side that
    /// wins over the box is that side's value there.
    using LaneIds = ValueId __attribute__((vector_size(sizeof(ValueId) * lanes)));
    struct ResolvedOperands {
        LaneIds a;
        LaneIds b;  // = a for unary ops (and Powi)
    };

    /// The walk of both evaluate()s, over the number type T (Interval or IntervalLanes).
    template <class T>
    T walk(const Tape& source, T* slots);
    /// For walk(): which side of a min or max wins over the box (in each
    /// lane): those lanes of `own` (the clause's value) become that side's,
    /// and choices_made_ counts them.
    void record_winners(Op op, const Interval& a, const Interval& b, const ResolvedOperands& v, LaneIds& own);
    void record_winners(Op op, const IntervalLanes& a, const IntervalLanes& b, const ResolvedOperands& v, LaneIds& own);
    /// walk() of four lanes compiled for AVX2 (x86-64 builds for older CPUs only).
    IntervalLanes walk_avx2(const Tape& source, IntervalLanes* slots);
    /// Writes the tape pruned to box `lane` of the last evaluate() into `out`.
    void simplify(Tape& out, int lane);

    const Tape* source_ = nullptr;  // of the last evaluate()
    std::vector<ResolvedOperands> operands_;  // per clause of source_: the values its operands are in each lane
    std::vector<LaneIds> slot_values_;        // during a walk: the value each slot holds, in each lane
    LaneIds result_value_{};                  // source_'s result, in each lane
    LaneIds choices_made_{};  // per lane: the mins and maxes with a winning side
    std::vector<Interval> slots_;
    std::vector<IntervalLanes> lane_slots_;         // made by the first lanes evaluate()
    std::vector<double> constant_value_;  // per slot of the source's constants: its value
    std::vector<std::uint64_t> clause_live_;      // a bit per clause of the source: live
    std::vector<std::uint32_t> constant_live_;    // per constant slot of the source: epoch_ once live
    std::vector<std::uint32_t> working_slot_;   // per live clause: its slot in the pruned tape
    std::vector<std::uint32_t> constant_slot_;  // per live constant: its slot in the pruned tape
    std::vector<std::uint32_t> free_slots_;     // a stack of the free working slots
    std::vector<Clause> kept_;                  // the kept clauses, filled from the end
    std::uint32_t epoch_ = 0;
};

}  // namespace zeroset
