// Three linear passes: interval evaluation that records min/max choices and
// which value each operand is (with chosen min/max resolved to their winner);
// a backward pass marking live values and counting their uses; a forward
// pass emitting the live clauses into fresh slots, freeing a slot at its
// value's last use.
#include "zeroset/expr/tape_pruner.hpp"

#include <algorithm>

namespace zeroset {

TapePruner::TapePruner(const Tape& full)
    : base_(full.slot_count()),
      slots_(full.slot_count()),
      value_in_slot_(full.slot_count()),
      choices_(full.clauses().size()),
      operand_a_(full.clauses().size()),
      operand_b_(full.clauses().size()),
      equals_(full.clauses().size()),
      live_(full.slot_count() + full.clauses().size(), 0),
      uses_(full.slot_count() + full.clauses().size()),
      new_slot_(full.slot_count() + full.clauses().size()) {}

Interval TapePruner::evaluate(const Tape& source, const Box3& box) {
    source_ = &source;
    choices_made_ = 0;
    Interval* s = slots_.data();
    s[Tape::slot_x] = {box.lo.x, box.hi.x};
    s[Tape::slot_y] = {box.lo.y, box.hi.y};
    s[Tape::slot_z] = {box.lo.z, box.hi.z};
    for (std::uint32_t v = 0; v < 3; ++v) value_in_slot_[v] = v;
    for (const auto& [slot, value] : source.constants()) {
        s[slot] = Interval(value);
        value_in_slot_[slot] = slot;
    }
    const auto resolved = [this](std::uint32_t id) { return is_clause_value(id) ? equals_[id - base_] : id; };
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        const bool binary = op_arity(c.op) == 2;
        const Interval a = s[c.a];
        const Interval& b = s[binary ? c.b : c.a];
        operand_a_[i] = resolved(value_in_slot_[c.a]);
        operand_b_[i] = binary ? resolved(value_in_slot_[c.b]) : operand_a_[i];
        choices_[i] = Choice::Both;
        if (c.op == Op::Min || c.op == Op::Max) {
            const bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;  // false for empty intervals
            if (c.op == Op::Min ? a_below : b_below) choices_[i] = Choice::Left;
            else if (c.op == Op::Min ? b_below : a_below) choices_[i] = Choice::Right;
            choices_made_ += choices_[i] != Choice::Both;
        }
        const auto id = static_cast<std::uint32_t>(base_ + i);
        equals_[i] = choices_[i] == Choice::Left ? operand_a_[i] : choices_[i] == Choice::Right ? operand_b_[i] : id;
        s[c.out] = apply_op<Interval>(c.op, a, b, static_cast<int>(c.b));
        value_in_slot_[c.out] = id;
    }
    return s[source.result_slot()];
}

void TapePruner::mark_live_values() {
    const Tape& source = *source_;
    if (++epoch_ == 0) {  // stamps wrapped: clear them once every 2^32 prunes
        std::fill(live_.begin(), live_.end(), 0);
        epoch_ = 1;
    }
    const auto use = [this](std::uint32_t id) {
        if (live_[id] != epoch_) {
            live_[id] = epoch_;
            uses_[id] = 0;
        }
        ++uses_[id];
    };
    // The result counts as one use that is never released, so its slot is
    // never handed to a later clause.
    const std::uint32_t root = value_in_slot_[source.result_slot()];
    use(is_clause_value(root) ? equals_[root - base_] : root);
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = clauses.size(); i-- > 0;) {
        // Only resolved ids are marked, so a live clause is never a chosen min/max.
        if (live_[base_ + i] != epoch_) continue;
        use(operand_a_[i]);
        if (op_arity(clauses[i].op) == 2) use(operand_b_[i]);
    }
}

void TapePruner::emit_live_clauses(Tape& out) {
    const Tape& source = *source_;
    out.clauses_.clear();
    out.constants_.clear();
    free_slots_.clear();
    for (std::uint32_t v = 0; v < 3; ++v) new_slot_[v] = v;
    std::uint32_t next_slot = 3;
    // Constants first: their slots are loaded once and must never be written.
    for (const auto& [slot, value] : source.constants()) {
        if (live_[slot] != epoch_) continue;
        new_slot_[slot] = next_slot;
        out.constants_.emplace_back(next_slot++, value);
    }
    const auto release = [this](std::uint32_t id) {
        if (is_clause_value(id) && --uses_[id] == 0) free_slots_.push_back(new_slot_[id]);
    };
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const auto id = static_cast<std::uint32_t>(base_ + i);
        if (live_[id] != epoch_) continue;
        const Clause& c = clauses[i];
        const bool binary = op_arity(c.op) == 2;
        // The output slot is taken before the operands' slots are released, so
        // it never aliases an operand (the batch evaluator relies on that).
        std::uint32_t slot = 0;
        if (free_slots_.empty()) {
            slot = next_slot++;
        } else {
            slot = free_slots_.back();
            free_slots_.pop_back();
        }
        out.clauses_.push_back(
            {c.op, slot, new_slot_[operand_a_[i]], binary ? new_slot_[operand_b_[i]] : c.b});
        new_slot_[id] = slot;
        release(operand_a_[i]);
        if (binary) release(operand_b_[i]);
    }
    const std::uint32_t root = value_in_slot_[source.result_slot()];
    out.result_slot_ = new_slot_[is_clause_value(root) ? equals_[root - base_] : root];
    out.slot_count_ = next_slot;
}

void TapePruner::simplify(Tape& out) {
    mark_live_values();
    emit_live_clauses(out);
}

}  // namespace zeroset
