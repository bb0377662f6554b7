// Interval evaluation with min/max choices, then a backward liveness pass
// and a forward pass that emits the live clauses with aliases resolved.
#include "zeroset/expr/tape_pruner.hpp"

#include <algorithm>
#include <stdexcept>

namespace zeroset {

TapePruner::TapePruner(const Tape& full)
    : slots_(full.slot_count()),
      choices_(full.clauses().size()),
      live_(full.slot_count(), 0),
      aliased_(full.slot_count(), 0),
      alias_of_(full.slot_count(), 0) {
    if (full.layout() != SlotLayout::OnePerValue)
        throw std::invalid_argument("TapePruner: the tape must use SlotLayout::OnePerValue");
    for (const auto& [slot, value] : full.constants()) slots_[slot] = Interval(value);
}

Interval TapePruner::evaluate(const Tape& source, const Box3& box) {
    Interval* s = slots_.data();
    s[Tape::slot_x] = {box.lo.x, box.hi.x};
    s[Tape::slot_y] = {box.lo.y, box.hi.y};
    s[Tape::slot_z] = {box.lo.z, box.hi.z};
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        const Interval a = s[c.a];
        choices_[i] = Choice::Both;
        if (c.op == Op::Min || c.op == Op::Max) {
            const Interval b = s[c.b];
            const bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;  // false for empty intervals
            if (c.op == Op::Min ? a_below : b_below) choices_[i] = Choice::Left;
            else if (c.op == Op::Min ? b_below : a_below) choices_[i] = Choice::Right;
        }
        const Interval& b = s[c.op == Op::Powi ? c.a : c.b];
        s[c.out] = apply_op<Interval>(c.op, a, b, static_cast<int>(c.b));
    }
    return s[source.result_slot()];
}

std::uint32_t TapePruner::resolve(std::uint32_t slot) const {
    while (aliased_[slot] == epoch_) slot = alias_of_[slot];
    return slot;
}

void TapePruner::keep_live_clauses(const Tape& source, Tape& out) {
    if (++epoch_ == 0) {  // stamps wrapped: clear them once every 2^32 prunes
        std::fill(live_.begin(), live_.end(), 0);
        std::fill(aliased_.begin(), aliased_.end(), 0);
        epoch_ = 1;
    }
    const std::vector<Clause>& clauses = source.clauses();
    live_[source.result_slot()] = epoch_;
    for (std::size_t i = clauses.size(); i-- > 0;) {
        const Clause& c = clauses[i];
        if (live_[c.out] != epoch_) continue;
        if (choices_[i] != Choice::Both) {
            const std::uint32_t winner = choices_[i] == Choice::Left ? c.a : c.b;
            aliased_[c.out] = epoch_;
            alias_of_[c.out] = winner;
            live_[winner] = epoch_;
            continue;
        }
        live_[c.a] = epoch_;
        if (op_arity(c.op) == 2) live_[c.b] = epoch_;
    }
    out.clauses_.clear();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        if (live_[c.out] != epoch_ || aliased_[c.out] == epoch_) continue;
        const bool binary = op_arity(c.op) == 2;
        out.clauses_.push_back({c.op, c.out, resolve(c.a), binary ? resolve(c.b) : c.b});
    }
    out.constants_ = source.constants_;
    out.slot_count_ = source.slot_count_;
    out.result_slot_ = resolve(source.result_slot());
}

Interval TapePruner::prune(const Tape& source, const Box3& box, Tape& out) {
    const Interval value = evaluate(source, box);
    keep_live_clauses(source, out);
    return value;
}

}  // namespace zeroset
