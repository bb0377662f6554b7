// Tape compilation: a post-order walk of the DAG (each shared node once), then
// slot assignment by last use.
#include "zeroset/expr/tape.hpp"

#include <algorithm>

#include <unordered_map>

namespace zeroset {

namespace {

bool is_leaf(Op op) { return op_arity(op) == 0; }

}  // namespace

Tape::Tape(const Expr& root) {
    // Models are written in a good schedule; keeping their order (of two
    // operands, the one made first is walked first) keeps few values live.
    const std::vector<Expr> order = operands_first(root);

    // Value number of each node = its index in `order`; find each value's last use.
    std::unordered_map<const void*, std::size_t> index;
    for (std::size_t i = 0; i < order.size(); ++i) index[order[i].id()] = i;
    std::vector<std::size_t> last_use(order.size(), 0);
    for (std::size_t i = 0; i < order.size(); ++i)
        for (int k = 0; k < op_arity(order[i].op()); ++k) last_use[index[order[i].operand(k).id()]] = i;

    std::vector<std::uint32_t> slot(order.size(), 0);
    std::vector<std::uint32_t> free_slots;
    slot_count_ = 3;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Expr& e = order[i];
        switch (e.op()) {
            case Op::VarX: slot[i] = slot_x; break;
            case Op::VarY: slot[i] = slot_y; break;
            case Op::VarZ: slot[i] = slot_z; break;
            case Op::Const:
                slot[i] = slot_count_++;
                constants_.emplace_back(slot[i], e.value());
                break;
            default: break;
        }
    }
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Expr& e = order[i];
        if (is_leaf(e.op())) continue;
        const int arity = op_arity(e.op());
        const std::uint32_t a = slot[index[e.operand(0).id()]];
        const std::uint32_t b =
            e.op() == Op::Powi ? static_cast<std::uint32_t>(e.exponent())
                               : (arity == 2 ? slot[index[e.operand(1).id()]] : 0u);
        // The output gets a slot before the operands' dead slots are freed, so
        // it never aliases an operand (the batch evaluator relies on that).
        if (free_slots.empty()) {
            slot[i] = slot_count_++;
        } else {
            slot[i] = free_slots.back();
            free_slots.pop_back();
        }
        for (int k = 0; k < arity; ++k) {
            const std::size_t operand = index[e.operand(k).id()];
            const bool already_freed = k == 1 && operand == index[e.operand(0).id()];
            if (!is_leaf(order[operand].op()) && last_use[operand] == i && !already_freed)
                free_slots.push_back(slot[operand]);
        }
        clauses_.push_back({e.op(), slot[i], a, b});
    }
    result_slot_ = slot[order.size() - 1];
}

bool Tape::has_choices() const {
    return std::any_of(clauses_.begin(), clauses_.end(), [](const Clause& c) { return c.op == Op::Min || c.op == Op::Max; });
}

bool Tape::is_polynomial() const {
    for (const Clause& c : clauses_) {
        switch (c.op) {
            case Op::Add: case Op::Sub: case Op::Mul: case Op::Neg: case Op::Square: break;
            case Op::Powi:
                if (static_cast<int>(c.b) < 0) return false;
                break;
            default: return false;
        }
    }
    return true;
}

}  // namespace zeroset
