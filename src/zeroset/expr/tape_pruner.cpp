// Interval evaluation follows which value each slot holds, in each lane's
// box — a min or max with a side that wins over the box holds that side's
// value — and records each clause's operands so resolved; simplification
// is one backward pass over the source tape.
#include "zeroset/expr/tape_pruner.hpp"

#include <algorithm>
#include <array>
#include <bit>

namespace zeroset {

TapePruner::TapePruner(const Tape& full)
    : operands_(full.clauses().size()),
      slot_values_(full.slot_count()),
      slots_(full.slot_count()),
      constant_value_(full.slot_count()),
      clause_live_((full.clauses().size() + 63) / 64, 0),
      constant_live_(full.slot_count(), 0),
      working_slot_(full.clauses().size()),
      constant_slot_(full.slot_count()) {}

// Which side of a min or max wins over the box, if one does (neither
// where an interval is empty: every comparison with NaN is false).
[[gnu::always_inline]] inline void TapePruner::record_winners(Op op, const Interval& a, const Interval& b,
                                                              const ResolvedOperands& v, LaneIds& own) {
    const bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;
    const bool left = op == Op::Min ? a_below : b_below, right = op == Op::Min ? b_below : a_below;
    if (!left && !right) return;
    own[0] = left ? v.a[0] : v.b[0];
    ++choices_made_[0];
}

// The same for four lanes at once, without a branch: each lane makes the
// one-box choice (left first). Whether any lane chose is as good as random
// from one clause to the next, so the selects and counts run every time.
[[gnu::always_inline]] inline void TapePruner::record_winners(Op op, const IntervalLanes& a, const IntervalLanes& b,
                                                              const ResolvedOperands& v, LaneIds& own) {
    using IdMask = std::int32_t __attribute__((vector_size(sizeof(std::int32_t) * lanes)));
    const IntervalLanes::Mask a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;
    const IntervalLanes::Mask left64 = op == Op::Min ? a_below : b_below;
    const IntervalLanes::Mask right64 = (op == Op::Min ? b_below : a_below) & ~left64;
    const IdMask left = __builtin_convertvector(left64, IdMask), right = __builtin_convertvector(right64, IdMask);
    own = left ? v.a : own;
    own = right ? v.b : own;
    choices_made_ -= std::bit_cast<LaneIds>(left | right);  // a chosen lane's mask is −1: one more
}

// Flattened: the op dispatch and the interval arithmetic are inlined into
// this loop, which is most of the cost of slicing a large model.
template <class T>
[[gnu::flatten]] T TapePruner::walk(const Tape& source, T* s) {
    source_ = &source;
    choices_made_ = LaneIds{};
    LaneIds* held = slot_values_.data();  // the value in each slot, in each lane
    for (ValueId v = 0; v < 3; ++v) held[v] = LaneIds{} + v;
    for (const auto& [slot, value] : source.constants()) {
        s[slot] = T(value);
        constant_value_[slot] = value;
        held[slot] = LaneIds{} + slot;
    }
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        const std::uint32_t second = op_arity(c.op) == 2 ? c.b : c.a;  // a unary op's (or Powi's) b is not a slot
        const T& a = s[c.a];
        const T& b = s[second];
        ResolvedOperands& v = operands_[i];
        v.a = held[c.a];
        v.b = held[second];
        LaneIds own = LaneIds{} + (clause_value | static_cast<ValueId>(i));
        if (c.op == Op::Min || c.op == Op::Max) record_winners(c.op, a, b, v, own);
        held[c.out] = own;
        s[c.out] = apply_op<T>(c.op, a, b, static_cast<int>(c.b));
    }
    result_value_ = held[source.result_slot()];
    return s[source.result_slot()];
}

Interval TapePruner::evaluate(const Tape& source, const Box3& box) {
    Interval* s = slots_.data();
    s[Tape::slot_x] = {box.lo.x, box.hi.x};
    s[Tape::slot_y] = {box.lo.y, box.hi.y};
    s[Tape::slot_z] = {box.lo.z, box.hi.z};
    return walk(source, s);
}

IntervalLanes TapePruner::evaluate(const Tape& source, std::span<const Box3, lanes> boxes) {
    if (lane_slots_.empty()) lane_slots_.resize(slots_.size());
    IntervalLanes* s = lane_slots_.data();
    for (int k = 0; k < lanes; ++k) {
        const Box3& box = boxes[static_cast<std::size_t>(k)];
        s[Tape::slot_x].set_lane(k, {box.lo.x, box.hi.x});
        s[Tape::slot_y].set_lane(k, {box.lo.y, box.hi.y});
        s[Tape::slot_z].set_lane(k, {box.lo.z, box.hi.z});
    }
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__)
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2) return walk_avx2(source, s);
#endif
    return walk(source, s);
}

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__)
// The lanes walk compiled for AVX2 as well, chosen by the CPU when it first
// runs: a vector of four doubles is one register there, two on plain x86-64.
// AVX2 without FMA, so that no product and sum fuse: every lane keeps the
// scalar code's bits.
[[gnu::target("avx2"), gnu::flatten]] IntervalLanes TapePruner::walk_avx2(const Tape& source, IntervalLanes* s) {
    return walk(source, s);
}
#endif

// One backward pass does liveness, slot allocation and emission: walking
// backwards, the first use of a value met is its last use, where it takes a
// slot; its definition frees the slot. Slots are final when taken.
//
// Liveness is a bitmap of the source's clauses, and the pass visits only its
// set bits, highest first (a clause's operands come before it, so marking
// them never adds a bit above the one being visited). Testing the clauses
// one by one cost a branch each, and whether a clause is live follows no
// pattern a predictor learns: on prospero.vm's slice this pass makes 30 %
// fewer mispredicted branches (by callgrind's model).
[[gnu::flatten]] void TapePruner::simplify(Tape& out, int lane) {
    const Tape& source = *source_;
    const std::vector<Clause>& clauses = source.clauses();
    const std::size_t n = clauses.size();
    const std::size_t words = (n + 63) / 64;
    std::uint64_t* live = clause_live_.data();
    std::fill_n(live, words, 0);
    if (++epoch_ == 0) {  // stamps wrapped: clear them once every 2^32 prunes
        std::fill(constant_live_.begin(), constant_live_.end(), 0);
        epoch_ = 1;
    }
    // The counters live in locals, which the compiler keeps in registers
    // (members could alias the arrays written below).
    const std::uint32_t epoch = epoch_;
    std::uint32_t free_count = 0, next_slot = 3;
    std::uint32_t *constant_live = constant_live_.data();
    std::uint32_t *working_slot = working_slot_.data(), *constant_slot = constant_slot_.data();
    const double* constant_value = constant_value_.data();
    out.constants_.clear();  // each live constant is added as it takes its slot
    std::size_t word = words;  // the word of the bitmap being visited …
    std::uint64_t unvisited = 0;  // … and its live clauses not visited yet
    // The slot of `v` in the pruned tape, taken at its last use (the first
    // seen walking backwards): a working slot freed at a value's definition,
    // or a new one; a constant's is never freed, as it is loaded once.
    const auto take_slot = [&](ValueId v) {
        if (v & clause_value) {
            const std::uint32_t j = v & ~clause_value;
            const std::uint64_t bit = std::uint64_t{1} << (j % 64);
            if (!(live[j / 64] & bit)) {
                live[j / 64] |= bit;
                unvisited |= j / 64 == word ? bit : 0;
                working_slot[j] = free_count > 0 ? free_slots_[--free_count] : next_slot++;
            }
            return working_slot[j];
        }
        if (v < 3) return v;
        if (constant_live[v] != epoch) {
            constant_live[v] = epoch;
            constant_slot[v] = next_slot;
            out.constants_.emplace_back(next_slot++, constant_value[v]);
        }
        return constant_slot[v];
    };
    const ResolvedOperands* operands = operands_.data();
    // At most every clause is kept, and each frees one slot.
    if (kept_.size() < n) {
        kept_.resize(n);
        free_slots_.resize(n);
    }

    const std::uint32_t root_slot = take_slot(result_value_[lane]);
    std::size_t first = n;  // the kept clauses fill kept_[first, n)
    while (word-- > 0) {
        for (unvisited = live[word]; unvisited != 0;) {
            const int k = 63 - std::countl_zero(unvisited);
            unvisited ^= std::uint64_t{1} << k;
            const std::size_t i = word * 64 + static_cast<std::size_t>(k);
            // Only resolved values take slots, so a live clause is never a chosen min/max.
            const Clause& c = clauses[i];
            const bool binary = op_arity(c.op) == 2;
            const ResolvedOperands& v = operands[i];
            const std::uint32_t slot_a = take_slot(v.a[lane]);
            const std::uint32_t slot_b = binary ? take_slot(v.b[lane]) : c.b;
            // Freed after the operands took theirs, so the output never aliases an
            // operand (the batch evaluator relies on that).
            free_slots_[free_count++] = working_slot[i];
            kept_[--first] = {c.op, working_slot[i], slot_a, slot_b};
        }
    }
    out.clauses_.assign(kept_.begin() + static_cast<std::ptrdiff_t>(first), kept_.begin() + static_cast<std::ptrdiff_t>(n));
    out.result_slot_ = root_slot;
    out.slot_count_ = next_slot;
}

}  // namespace zeroset
