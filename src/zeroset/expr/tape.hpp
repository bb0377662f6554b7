// Tape: an expression compiled to a flat, topologically ordered list of
// clauses {op, out, a, b} over numbered slots — the form every evaluator walks.
// Slots 0, 1, 2 hold x, y, z; every distinct constant has a slot of its own
// (loaded once, never overwritten); working slots are reused once their value
// is dead (linear-scan register allocation), so a 10 000-clause model needs only a
// few hundred slots and stays in cache. A clause's output slot never aliases
// one of its operands (the batch evaluator relies on that). Tapes pruned to a
// box (expr/tape_pruner.hpp) follow the same rules with their own numbering.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "zeroset/expr/expr.hpp"

namespace zeroset {

struct Clause {
    Op op;
    std::uint32_t out;
    std::uint32_t a;
    std::uint32_t b;  // second operand slot; for Powi the exponent (as int)
};

class Tape {
public:
    static constexpr std::uint32_t slot_x = 0, slot_y = 1, slot_z = 2;

    explicit Tape(const Expr& root);
    /// An empty tape, to be filled by TapePruner.
    Tape() = default;

    [[nodiscard]] const std::vector<Clause>& clauses() const { return clauses_; }
    [[nodiscard]] const std::vector<std::pair<std::uint32_t, double>>& constants() const { return constants_; }
    [[nodiscard]] std::uint32_t slot_count() const { return slot_count_; }
    [[nodiscard]] std::uint32_t result_slot() const { return result_slot_; }
    /// True when every op is +, −, ×, neg, square or powi with n ≥ 0.
    [[nodiscard]] bool is_polynomial() const;
    /// True when a min or max occurs: what tape pruning can remove.
    [[nodiscard]] bool has_choices() const;

private:
    friend class TapePruner;

    std::vector<Clause> clauses_;
    std::vector<std::pair<std::uint32_t, double>> constants_;
    std::uint32_t slot_count_ = 3;
    std::uint32_t result_slot_ = 0;
};

}  // namespace zeroset
