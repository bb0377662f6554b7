// Interval evaluation records, for each min and max, the side that wins over
// the box and so which value it equals (values followed by their ids,
// Tape::operand_values); simplification is one backward pass over the
// source tape and one over the clauses it keeps.
#include "zeroset/expr/tape_pruner.hpp"

#include <algorithm>

namespace zeroset {

TapePruner::TapePruner(const Tape& full)
    : slots_(full.slot_count()),
      choices_(full.clauses().size()),
      equals_(full.clauses().size()),
      clause_live_(full.clauses().size(), 0),
      constant_live_(full.slot_count(), 0),
      working_slot_(full.clauses().size()),
      emitted_at_(full.clauses().size()),
      constant_index_(full.slot_count()) {}

// Flattened: the op dispatch and the interval arithmetic are inlined into
// this loop, which is most of the cost of slicing a large model.
[[gnu::flatten]] Interval TapePruner::evaluate(const Tape& source, const Box3& box) {
    source_ = &source;
    choices_made_ = 0;
    Interval* s = slots_.data();
    s[Tape::slot_x] = {box.lo.x, box.hi.x};
    s[Tape::slot_y] = {box.lo.y, box.hi.y};
    s[Tape::slot_z] = {box.lo.z, box.hi.z};
    for (const auto& [slot, value] : source.constants()) s[slot] = Interval(value);
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = 0; i < clauses.size(); ++i) {
        const Clause& c = clauses[i];
        const Interval a = s[c.a];
        const Interval b = s[op_arity(c.op) == 2 ? c.b : c.a];
        Choice choice = Choice::Both;
        if (c.op == Op::Min || c.op == Op::Max) {
            const bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;  // false for empty intervals
            if (c.op == Op::Min ? a_below : b_below) choice = Choice::Left;
            else if (c.op == Op::Min ? b_below : a_below) choice = Choice::Right;
            if (choice != Choice::Both) {
                const ClauseOperands& v = source.operand_values()[i];
                equals_[i] = resolve(choice == Choice::Left ? v.a : v.b);
                ++choices_made_;
            }
        }
        choices_[i] = choice;
        s[c.out] = apply_op<Interval>(c.op, a, b, static_cast<int>(c.b));
    }
    return s[source.result_slot()];
}

namespace {
// How take_slot() marks a slot until the pruned tape's layout is known
// (x, y and z keep slots 0, 1, 2 and are not marked).
constexpr std::uint32_t working_mark = std::uint32_t{1} << 30;
constexpr std::uint32_t constant_mark = std::uint32_t{1} << 29;
}  // namespace

inline std::uint32_t TapePruner::take_slot(ValueId v) {
    if (v & clause_value) {
        const std::uint32_t j = v & ~clause_value;
        if (clause_live_[j] != epoch_) {
            clause_live_[j] = epoch_;
            if (free_slots_.empty()) {
                working_slot_[j] = working_slots_++;
            } else {
                working_slot_[j] = free_slots_.back();
                free_slots_.pop_back();
            }
        }
        return working_mark | working_slot_[j];
    }
    if (v < 3) return v;
    if (constant_live_[v] != epoch_) {
        constant_live_[v] = epoch_;
        constant_index_[v] = constants_++;
    }
    return constant_mark | constant_index_[v];
}

// Constants take the slots after x, y, z (loaded once, never written), then
// the working slots.
std::uint32_t TapePruner::final_slot(std::uint32_t encoded) const {
    if (encoded & working_mark) return 3 + constants_ + (encoded & ~working_mark);
    if (encoded & constant_mark) return 3 + (encoded & ~constant_mark);
    return encoded;
}

ValueId TapePruner::final_value(ValueId v) const {
    if (v & clause_value) return clause_value | (emitted_ - 1 - emitted_at_[v & ~clause_value]);
    return v < 3 ? v : 3 + constant_index_[v];
}

// One backward pass does liveness, slot allocation and emission: walking
// backwards, the first use of a value met is its last use, where it takes a
// slot; its definition frees the slot. The clauses come out reversed and with
// marked slots; a pass over the live clauses alone puts them in order with
// their final slots.
void TapePruner::simplify(Tape& out) {
    const Tape& source = *source_;
    if (++epoch_ == 0) {  // stamps wrapped: clear them once every 2^32 prunes
        std::fill(clause_live_.begin(), clause_live_.end(), 0);
        std::fill(constant_live_.begin(), constant_live_.end(), 0);
        epoch_ = 1;
    }
    free_slots_.clear();
    working_slots_ = constants_ = 0;
    reversed_.clear();
    reversed_operands_.clear();

    const ValueId root = resolve(source.result_value());
    const std::uint32_t root_slot = take_slot(root);
    const std::vector<Clause>& clauses = source.clauses();
    for (std::size_t i = clauses.size(); i-- > 0;) {
        // Only resolved values take slots, so a live clause is never a chosen min/max.
        if (clause_live_[i] != epoch_) continue;
        const Clause& c = clauses[i];
        const bool binary = op_arity(c.op) == 2;
        const ClauseOperands& v = source.operand_values()[i];
        const ValueId a = resolve(v.a), b = binary ? resolve(v.b) : a;
        const std::uint32_t slot_a = take_slot(a), slot_b = binary ? take_slot(b) : c.b;
        // Freed after the operands took theirs, so the output never aliases an
        // operand (the batch evaluator relies on that).
        free_slots_.push_back(working_slot_[i]);
        emitted_at_[i] = static_cast<std::uint32_t>(reversed_.size());
        reversed_.push_back({c.op, working_mark | working_slot_[i], slot_a, slot_b});
        reversed_operands_.push_back({a, b});
    }

    emitted_ = static_cast<std::uint32_t>(reversed_.size());
    out.clauses_.resize(emitted_);
    out.operand_values_.resize(emitted_);
    for (std::size_t k = 0; k < emitted_; ++k) {
        const Clause& c = reversed_[emitted_ - 1 - k];
        const bool binary = op_arity(c.op) == 2;
        out.clauses_[k] = {c.op, final_slot(c.out), final_slot(c.a), binary ? final_slot(c.b) : c.b};
        const ClauseOperands& v = reversed_operands_[emitted_ - 1 - k];
        out.operand_values_[k] = {final_value(v.a), final_value(v.b)};
    }
    out.constants_.resize(constants_);
    for (const auto& [slot, value] : source.constants()) {
        if (constant_live_[slot] == epoch_) out.constants_[constant_index_[slot]] = {3 + constant_index_[slot], value};
    }
    out.result_slot_ = final_slot(root_slot);
    out.result_value_ = final_value(root);
    out.slot_count_ = 3 + constants_ + working_slots_;
}

}  // namespace zeroset
