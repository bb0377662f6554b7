// Interval evaluation records, for each min and max, the side that wins over
// the box and so which value it equals (values followed by their ids,
// Tape::operand_values); simplification is one backward pass over the
// source tape, and one over the clauses it keeps for their value ids.
#include "zeroset/expr/tape_pruner.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

namespace zeroset {

TapePruner::TapePruner(const Tape& full)
    : slots_(full.slot_count()),
      equals_(full.clauses().size()),
      constant_value_(full.slot_count()),
      clause_live_(full.clauses().size(), 0),
      constant_live_(full.slot_count(), 0),
      working_slot_(full.clauses().size()),
      emitted_at_(full.clauses().size()),
      constant_slot_(full.slot_count()) {}

// Which side of a min or max wins over the box, if one does (neither
// where an interval is empty: every comparison with NaN is false).
[[gnu::always_inline]] inline void TapePruner::record_winners(Op op, const Interval& a, const Interval& b,
                                                              const ClauseOperands& v, std::array<ValueId, lanes>& equals) {
    const bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;
    const bool left = op == Op::Min ? a_below : b_below, right = op == Op::Min ? b_below : a_below;
    if (!left && !right) return;
    equals[0] = resolve(left ? v.a : v.b, 0);
    ++choices_made_[0];
}

// The same for four lanes at once, without a branch a lane: each lane
// makes the one-box choice (left first).
[[gnu::always_inline]] inline void TapePruner::record_winners(Op op, const IntervalLanes& a, const IntervalLanes& b,
                                                              const ClauseOperands& v, std::array<ValueId, lanes>& equals) {
    using Ids = ValueId __attribute__((vector_size(16)));
    using IdMask = std::int32_t __attribute__((vector_size(16)));
    const IntervalLanes::Mask a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;
    const IntervalLanes::Mask left64 = op == Op::Min ? a_below : b_below;
    const IntervalLanes::Mask right64 = (op == Op::Min ? b_below : a_below) & ~left64;
    const IdMask left = __builtin_convertvector(left64, IdMask), right = __builtin_convertvector(right64, IdMask);
    const IdMask chosen = left | right;
    if ((chosen[0] | chosen[1] | chosen[2] | chosen[3]) == 0) return;
    // An operand's value over each lane's box: a clause's own winners, or a constant or variable.
    const auto lanes_of = [&](ValueId id) {
        if ((id & clause_value) == 0) return Ids{id, id, id, id};
        Ids row;
        std::memcpy(&row, equals_[id & ~clause_value].data(), sizeof row);
        return row;
    };
    Ids row;
    std::memcpy(&row, equals.data(), sizeof row);
    row = left ? lanes_of(v.a) : row;
    row = right ? lanes_of(v.b) : row;
    std::memcpy(equals.data(), &row, sizeof row);
    for (std::size_t k = 0; k < static_cast<std::size_t>(lanes); ++k) choices_made_[k] += chosen[k] != 0;
}

// Flattened: the op dispatch and the interval arithmetic are inlined into
// this loop, which is most of the cost of slicing a large model.
template <class T>
[[gnu::flatten]] T TapePruner::walk(const Tape& source, T* s) {
    if (!source.prunable()) throw std::logic_error("a tape made without value ids cannot be pruned again");
    source_ = &source;
    choices_made_.fill(0);
    for (const auto& [slot, value] : source.constants()) {
        s[slot] = T(value);
        constant_value_[slot] = value;
    }
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        const T& a = s[c.a];
        const T& b = s[op_arity(c.op) == 2 ? c.b : c.a];
        std::array<ValueId, lanes>& equals = equals_[i];
        equals.fill(clause_value | static_cast<ValueId>(i));
        if (c.op == Op::Min || c.op == Op::Max) record_winners(c.op, a, b, source.operand_values()[i], equals);
        s[c.out] = apply_op<T>(c.op, a, b, static_cast<int>(c.b));
    }
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
// slot; its definition frees the slot. Slots are final when taken; only the
// clauses' value ids wait for the count of kept clauses.
[[gnu::flatten]] void TapePruner::simplify(Tape& out, int lane, ValueIds ids) {
    const Tape& source = *source_;
    if (++epoch_ == 0) {  // stamps wrapped: clear them once every 2^32 prunes
        std::fill(clause_live_.begin(), clause_live_.end(), 0);
        std::fill(constant_live_.begin(), constant_live_.end(), 0);
        epoch_ = 1;
    }
    // The counters live in locals, which the compiler keeps in registers
    // (members could alias the arrays written below).
    const std::uint32_t epoch = epoch_;
    std::uint32_t free_count = 0, next_slot = 3;
    std::uint32_t *clause_live = clause_live_.data(), *constant_live = constant_live_.data();
    std::uint32_t *working_slot = working_slot_.data(), *constant_slot = constant_slot_.data();
    const double* constant_value = constant_value_.data();
    out.constants_.clear();  // each live constant is added as it takes its slot
    // The slot of `v` in the pruned tape, taken at its last use (the first
    // seen walking backwards): a working slot freed at a value's definition,
    // or a new one; a constant's is never freed, as it is loaded once.
    const auto take_slot = [&](ValueId v) {
        if (v & clause_value) {
            const std::uint32_t j = v & ~clause_value;
            if (clause_live[j] != epoch) {
                clause_live[j] = epoch;
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
    const std::vector<Clause>& clauses = source.clauses();
    const std::vector<ClauseOperands>& operands = source.operand_values();
    const std::size_t n = clauses.size();
    // At most every clause is kept, and each frees one slot.
    if (kept_.size() < n) {
        kept_.resize(n);
        kept_operands_.resize(n);
        free_slots_.resize(n);
    }
    const bool with_ids = ids == ValueIds::Keep;

    const ValueId root = resolve(source.result_value(), lane);
    const std::uint32_t root_slot = take_slot(root);
    std::size_t first = n;  // the kept clauses fill kept_[first, n)
    for (std::size_t i = n; i-- > 0;) {
        // Only resolved values take slots, so a live clause is never a chosen min/max.
        if (clause_live[i] != epoch) continue;
        const Clause& c = clauses[i];
        const bool binary = op_arity(c.op) == 2;
        const ClauseOperands& v = operands[i];
        const ValueId a = resolve(v.a, lane), b = binary ? resolve(v.b, lane) : a;
        const std::uint32_t slot_a = take_slot(a), slot_b = binary ? take_slot(b) : c.b;
        // Freed after the operands took theirs, so the output never aliases an
        // operand (the batch evaluator relies on that).
        free_slots_[free_count++] = working_slot[i];
        kept_[--first] = {c.op, working_slot[i], slot_a, slot_b};
        if (with_ids) {
            emitted_at_[i] = static_cast<std::uint32_t>(first);
            kept_operands_[first] = {a, b};  // the source's ids, renumbered below
        }
    }

    out.clauses_.assign(kept_.begin() + static_cast<std::ptrdiff_t>(first), kept_.begin() + static_cast<std::ptrdiff_t>(n));
    // A clause's value id is its place in the pruned tape; a constant's is its slot.
    const auto renumber = [&](ValueId v) -> ValueId {
        if (v & clause_value) return clause_value | (emitted_at_[v & ~clause_value] - static_cast<std::uint32_t>(first));
        return v < 3 ? v : constant_slot[v];
    };
    out.operand_values_.resize(with_ids ? n - first : 0);
    if (with_ids)
        for (std::size_t k = first; k < n; ++k)
            out.operand_values_[k - first] = {renumber(kept_operands_[k].a), renumber(kept_operands_[k].b)};
    out.result_slot_ = root_slot;
    // The root is the last kept clause when it is a clause's value.
    const auto last_kept = static_cast<ValueId>(n - first - 1);
    out.result_value_ = with_ids ? renumber(root) : (root & clause_value) ? clause_value | last_kept : renumber(root);
    out.slot_count_ = next_slot;
}

}  // namespace zeroset
