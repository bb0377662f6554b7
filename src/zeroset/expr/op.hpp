// The op table: every operation an implicit function may use, in one place.
// A row gives the op's name, its name in fidget's .vm format, its arity and
// its meaning as an expression over the operands `a`, `b` and the integer
// immediate `n` — written once for every number type, which each provide
// the named functions (square, sqrt, …; see math/scalar.hpp, interval.hpp,
// dual.hpp, jet.hpp). Adding an op: one row here, one function per number type.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "zeroset/math/scalar.hpp"

// X(Name, vm_name, arity, expression)
#define ZEROSET_OPS(X)                             \
    X(Const, "const", 0, a)                        \
    X(VarX, "var-x", 0, a)                         \
    X(VarY, "var-y", 0, a)                         \
    X(VarZ, "var-z", 0, a)                         \
    X(Add, "add", 2, a + b)                        \
    X(Sub, "sub", 2, a - b)                        \
    X(Mul, "mul", 2, a * b)                        \
    X(Div, "div", 2, a / b)                        \
    X(Neg, "neg", 1, -a)                           \
    X(Square, "square", 1, square(a))              \
    X(Sqrt, "sqrt", 1, sqrt(a))                    \
    X(Abs, "abs", 1, abs(a))                       \
    X(Exp, "exp", 1, exp(a))                       \
    X(Log, "ln", 1, log(a))                        \
    X(Sin, "sin", 1, sin(a))                       \
    X(Cos, "cos", 1, cos(a))                       \
    X(Tan, "tan", 1, tan(a))                       \
    X(Atan, "atan", 1, atan(a))                    \
    X(Atan2, "atan2", 2, atan2(a, b))              \
    X(Floor, "floor", 1, floor(a))                 \
    X(Hypot, "hypot", 2, hypot(a, b))              \
    X(LogSumExp, "log-sum-exp", 2, log_sum_exp(a, b)) \
    X(Powi, "powi", 1, powi(a, n))                 \
    X(Pow, "pow", 2, pow(a, b))                    \
    X(Min, "min", 2, min(a, b))                    \
    X(Max, "max", 2, max(a, b))

namespace zeroset {

enum class Op : std::uint8_t {
#define ZEROSET_OP_ENUM(name, vm, arity, expr) name,
    ZEROSET_OPS(ZEROSET_OP_ENUM)
#undef ZEROSET_OP_ENUM
};

inline constexpr int op_count = 0
#define ZEROSET_OP_COUNT(name, vm, arity, expr) +1
    ZEROSET_OPS(ZEROSET_OP_COUNT)
#undef ZEROSET_OP_COUNT
    ;

/// Number of expression operands (Powi's exponent is an immediate, not an operand).
/// A table rather than a switch: tape walks ask for every clause, and a
/// load does not branch.
inline constexpr std::uint8_t op_arities[] = {
#define ZEROSET_OP_ARITY(name, vm, arity, expr) arity,
    ZEROSET_OPS(ZEROSET_OP_ARITY)
#undef ZEROSET_OP_ARITY
};
constexpr int op_arity(Op op) { return op_arities[static_cast<std::uint8_t>(op)]; }

/// The op's name in fidget's .vm format (also used when printing).
constexpr std::string_view op_name(Op op) {
    switch (op) {
#define ZEROSET_OP_NAME(name, vm, arity, expr) \
    case Op::name:                             \
        return vm;
        ZEROSET_OPS(ZEROSET_OP_NAME)
#undef ZEROSET_OP_NAME
    }
    return "?";
}

std::optional<Op> op_from_name(std::string_view name);

/// Applies a non-leaf op to operands of any number type T.
template <class T>
inline T apply_op(Op op, const T& a, const T& b, int n) {
    (void)b;
    (void)n;
    switch (op) {
#define ZEROSET_OP_APPLY(name, vm, arity, expr) \
    case Op::name:                              \
        return expr;
        ZEROSET_OPS(ZEROSET_OP_APPLY)
#undef ZEROSET_OP_APPLY
    }
    return a;
}

}  // namespace zeroset
