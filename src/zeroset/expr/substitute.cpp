// Iterative, memoised rebuilding of the DAG (the walk of tape.cpp).
#include "zeroset/expr/substitute.hpp"

#include <unordered_map>
#include <utility>
#include <vector>

namespace zeroset {

namespace {

/// The node `op` over new operands, through the builders that simplify
/// (x + 0, x·1, −−x, min(a, a)…), else Expr::make, which folds constants.
Expr rebuild(const Expr& node, const Expr& a, const Expr& b) {
    switch (node.op()) {
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Neg: return -a;
        case Op::Min: return min(a, b);
        case Op::Max: return max(a, b);
        default: return Expr::make(node.op(), a, b, node.op() == Op::Powi ? node.exponent() : 0);
    }
}

}  // namespace

ExprPoint coordinates() { return {var_x(), var_y(), var_z()}; }

Expr substitute(const Expr& f, const ExprPoint& p) {
    // f(x, y, z) is f: a POV-Ray function called as F(x, y, z) — in a loop
    // that redefines F from itself, say — costs nothing per call.
    if (p.x == var_x() && p.y == var_y() && p.z == var_z()) return f;
    std::unordered_map<const void*, Expr> done;
    done.emplace(var_x().id(), p.x);
    done.emplace(var_y().id(), p.y);
    done.emplace(var_z().id(), p.z);
    std::vector<std::pair<Expr, bool>> stack{{f, false}};  // (node, operands done)
    while (!stack.empty()) {
        auto [e, expanded] = stack.back();
        stack.pop_back();
        if (done.contains(e.id())) continue;
        const int arity = op_arity(e.op());
        if (arity == 0) {  // a constant: unchanged
            done.emplace(e.id(), e);
            continue;
        }
        if (!expanded) {
            stack.emplace_back(e, true);
            for (int i = arity - 1; i >= 0; --i) {
                const Expr child = e.operand(i);
                if (!done.contains(child.id())) stack.emplace_back(child, false);
            }
            continue;
        }
        const Expr a = done.at(e.operand(0).id());
        const Expr b = arity == 2 ? done.at(e.operand(1).id()) : Expr();
        done.emplace(e.id(), rebuild(e, a, b));
    }
    return done.at(f.id());
}

}  // namespace zeroset
