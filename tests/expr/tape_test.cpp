// Tape: one clause per distinct non-leaf node, topological order, register
// allocation that reuses dead slots but never lets a clause's output alias
// its operands.
#include "zeroset/expr/tape.hpp"

#include <gtest/gtest.h>
#include "support/models.hpp"

#include <fstream>
#include <set>
#include <unordered_set>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/vm_import.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

/// Distinct non-leaf nodes of the DAG.
std::size_t non_leaf_count(const Expr& root) {
    std::unordered_set<const void*> seen;
    std::vector<Expr> stack{root};
    std::size_t count = 0;
    while (!stack.empty()) {
        const Expr e = stack.back();
        stack.pop_back();
        if (!seen.insert(e.id()).second) continue;
        const int arity = op_arity(e.op());
        if (arity > 0) ++count;
        for (int i = 0; i < arity; ++i) stack.push_back(e.operand(i));
    }
    return count;
}

Expr load(const char* name) {
    std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
    EXPECT_TRUE(in) << name;
    return import_vm(in);
}

bool is_operand_slot(const Clause& c, std::uint32_t s) {
    if (c.a == s) return true;
    return op_arity(c.op) == 2 && c.b == s;
}

/// Structural checks every tape must pass; also replays the slot lifetimes.
void check_tape(const Tape& tape) {
    std::set<std::uint32_t> constant_slots;
    for (const auto& [slot, value] : tape.constants()) {
        EXPECT_GE(slot, 3u);
        EXPECT_LT(slot, tape.slot_count());
        EXPECT_TRUE(constant_slots.insert(slot).second) << "two constants in slot " << slot;
    }
    // A slot is readable once written: x, y, z and the constants from the start.
    std::vector<bool> written(tape.slot_count(), false);
    written[Tape::slot_x] = written[Tape::slot_y] = written[Tape::slot_z] = true;
    for (const std::uint32_t s : constant_slots) written[s] = true;
    for (std::size_t i = 0; i < tape.clauses().size(); ++i) {
        const Clause& c = tape.clauses()[i];
        ASSERT_LT(c.out, tape.slot_count());
        ASSERT_LT(c.a, tape.slot_count());
        ASSERT_TRUE(written[c.a]) << "clause " << i << " reads slot " << c.a << " before it is written";
        if (op_arity(c.op) == 2) {
            ASSERT_LT(c.b, tape.slot_count());
            ASSERT_TRUE(written[c.b]) << "clause " << i << " reads slot " << c.b << " before it is written";
        }
        // The batch evaluator's __restrict relies on this.
        ASSERT_FALSE(is_operand_slot(c, c.out)) << "clause " << i << " writes its own operand slot " << c.out;
        ASSERT_GE(c.out, 3u) << "clause " << i << " overwrites x, y or z";
        ASSERT_FALSE(constant_slots.contains(c.out)) << "clause " << i << " overwrites a constant";
        written[c.out] = true;
    }
    ASSERT_LT(tape.result_slot(), tape.slot_count());
}

/// The tape's value by naive recursive evaluation of the DAG (no slots at all).
double reference(const Expr& e, double x, double y, double z) {
    switch (e.op()) {
        case Op::Const:
            return e.value();
        case Op::VarX:
            return x;
        case Op::VarY:
            return y;
        case Op::VarZ:
            return z;
        default: {
            const double a = reference(e.operand(0), x, y, z);
            const double b = op_arity(e.op()) == 2 ? reference(e.operand(1), x, y, z) : 0.0;
            return apply_op<double>(e.op(), a, b, e.exponent());
        }
    }
}

TEST(Tape, OneClausePerDistinctNonLeafNode) {
    const Expr r = sqrt(square(X) + square(Y) + square(Z));
    const Expr f = max(r - 1.0, -(r - 0.5)) + sin(r) * r;  // r is shared four times
    const Tape tape(f);
    EXPECT_EQ(tape.clauses().size(), non_leaf_count(f));
    EXPECT_EQ(tape.clauses().size(), 9u);  // r is two hypots
    check_tape(tape);
    Evaluator<double> eval(tape);
    for (const double x : {-1.0, 0.3, 2.0}) EXPECT_DOUBLE_EQ(eval(x, 0.5, -0.25), reference(f, x, 0.5, -0.25));
}

TEST(Tape, EachConstantIsLoadedOnce) {
    const Expr f = (X + 2.0) * (Y + 2.0) + (Z + 2.0) * 3.0;
    const Tape tape(f);
    EXPECT_EQ(tape.constants().size(), 2u);  // 2 and 3
    check_tape(tape);
    Evaluator<double> eval(tape);
    EXPECT_DOUBLE_EQ(eval(1, 2, 3), 3.0 * 4.0 + 5.0 * 3.0);
}

TEST(Tape, RootIsAConstant) {
    const Tape tape(Expr(4.25));
    EXPECT_TRUE(tape.clauses().empty());
    check_tape(tape);
    EXPECT_EQ(Evaluator<double>(tape)(1, 2, 3), 4.25);
    Evaluator<Interval> ei(tape);
    const Interval i = ei(Interval(-1, 1), Interval(-1, 1), Interval(-1, 1));
    EXPECT_EQ(i.lo, 4.25);
    EXPECT_EQ(i.hi, 4.25);
    Evaluator<Dual<double>> ed(tape);
    EXPECT_EQ(evaluate_gradient(ed, {1, 2, 3}).g, (Vec3d{0, 0, 0}));
    Evaluator<Jet<double>> ej(tape);
    const Jet<double> j = evaluate_along_ray(ej, {1, 2, 3}, {1, 1, 1}, 0.5);
    EXPECT_EQ(j.v, 4.25);
    EXPECT_EQ(j.d1, 0.0);
    EXPECT_EQ(j.d2, 0.0);
    EXPECT_TRUE(tape.is_polynomial());
}

TEST(Tape, RootIsAVariable) {
    for (const auto& [v, axis] : {std::pair{X, 0}, std::pair{Y, 1}, std::pair{Z, 2}}) {
        const Tape tape(v);
        EXPECT_TRUE(tape.clauses().empty());
        EXPECT_EQ(tape.result_slot(), static_cast<std::uint32_t>(axis));
        check_tape(tape);
        Evaluator<double> e(tape);
        EXPECT_EQ(e(1, 2, 3), 1.0 + axis);
        Evaluator<Dual<double>> ed(tape);
        const Dual<double> d = evaluate_gradient(ed, {1, 2, 3});
        for (int k = 0; k < 3; ++k) EXPECT_EQ(d.g[k], k == axis ? 1.0 : 0.0);
        Evaluator<Jet<double>> ej(tape);
        const Jet<double> j = evaluate_along_ray(ej, {1, 2, 3}, {4, 5, 6}, 2.0);
        EXPECT_EQ(j.v, (Vec3d{9, 12, 15})[axis]);
        EXPECT_EQ(j.d1, (Vec3d{4, 5, 6})[axis]);
    }
}

TEST(Tape, SquaringAValueReadsOneSlotTwice) {
    // a·a, min(a, a)-like patterns: the operand is freed once, not twice
    // (a double free would hand the same slot to two live values).
    const Expr a = sin(X) + 1.0;
    const Expr f = (a * a) * cos(Y) + (a * a) / (cos(Y) + 3.0) + Expr::make(Op::Max, a, a);
    const Tape tape(f);
    check_tape(tape);
    Evaluator<double> eval(tape);
    for (const double x : {-2.0, 0.1, 1.0}) EXPECT_DOUBLE_EQ(eval(x, 0.7, 0.0), reference(f, x, 0.7, 0.0));
}

TEST(Tape, RegisterAllocationOnRealModels) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    for (const char* name : {"bear.vm", "prospero.vm"}) {
        SCOPED_TRACE(name);
        const Expr model = load(name);
        const Tape tape(model);
        const std::size_t clauses = tape.clauses().size();
        EXPECT_EQ(clauses, non_leaf_count(model));
        EXPECT_GT(clauses, 300u);
        // Dead slots are reused: far fewer working slots than clauses.
        const std::size_t working = tape.slot_count() - 3 - tape.constants().size();
        EXPECT_LT(working * 10, clauses) << working << " working slots for " << clauses << " clauses";
        EXPECT_LT(tape.slot_count() * 3, clauses);  // constants included
        check_tape(tape);
    }
}

TEST(Tape, SlotReuseGivesTheRightValues) {
    // A long chain with many short-lived temporaries, checked against the DAG.
    Expr f = X;
    for (int i = 0; i < 200; ++i) {
        const double c = 0.01 * i;
        f = min(f, sqrt(square(X - c) + square(Y + c)) - 0.5) + 0.001 * sin(Z * static_cast<double>(i));
    }
    const Tape tape(f);
    check_tape(tape);
    // Post-order visits a commutative op's operands in an arbitrary (address)
    // order, so a side term may stay live across the whole chain: about one
    // slot per link, still far fewer than the clauses.
    EXPECT_LT((tape.slot_count() - 3 - tape.constants().size()) * 5, tape.clauses().size());
    Evaluator<double> eval(tape);
    for (const double x : {-1.0, 0.25, 1.5}) EXPECT_DOUBLE_EQ(eval(x, -0.3, 0.8), reference(f, x, -0.3, 0.8));
}

TEST(Tape, IsPolynomial) {
    EXPECT_TRUE(Tape(square(X) * Y - powi(Z, 3) + 2.0).is_polynomial());
    EXPECT_TRUE(Tape(-X).is_polynomial());
    EXPECT_FALSE(Tape(powi(X, -2)).is_polynomial());
    EXPECT_FALSE(Tape(X / Y).is_polynomial());
    EXPECT_FALSE(Tape(sqrt(X)).is_polynomial());
    EXPECT_FALSE(Tape(min(X, Y)).is_polynomial());
    EXPECT_FALSE(Tape(abs(X)).is_polynomial());
    for (const Expr& f : {tan(X), atan(X), atan2(X, Y), floor(X), hypot(X, Y)}) EXPECT_FALSE(Tape(f).is_polynomial());
}

}  // namespace
}  // namespace zeroset
