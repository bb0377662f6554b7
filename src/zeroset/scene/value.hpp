// Value: what a scene expression evaluates to — a number (an Expr in x, y, z)
// or a vector (a, b, c) of three numbers. Each key of a block says which it
// needs. A constant number is kept as a plain double: a loop of arithmetic
// on constants (a generated scene of 10⁵ components) would otherwise make
// and hash-cons an expression node for every step. Expr's constant folding
// gives the same double, so nothing depends on which form a constant has.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "zeroset/expr/expr.hpp"

namespace zeroset {

using ExprVector = std::array<Expr, 3>;

class Value {
public:
    Value(double constant) : value_(constant) {}  // NOLINT: a number is a Value
    Value(Expr number) {                            // NOLINT: so is an expression
        if (number.is_constant())
            value_ = number.value();
        else
            value_ = std::move(number);
    }
    Value(ExprVector vector) : value_(std::move(vector)) {}  // NOLINT: and a vector

    [[nodiscard]] bool is_vector() const { return std::holds_alternative<ExprVector>(value_); }
    /// A number that depends on none of x, y, z.
    [[nodiscard]] bool is_constant() const { return std::holds_alternative<double>(value_); }
    [[nodiscard]] double constant() const { return std::get<double>(value_); }
    /// The number (not a vector) as an expression.
    [[nodiscard]] Expr number() const { return is_constant() ? Expr(constant()) : std::get<Expr>(value_); }
    [[nodiscard]] const ExprVector& vector() const { return std::get<ExprVector>(value_); }
    /// "a number" or "a vector", for messages.
    [[nodiscard]] std::string_view kind_name() const { return is_vector() ? "a vector" : "a number"; }

private:
    std::variant<double, Expr, ExprVector> value_;
};

/// The coordinates an expression depends on, for messages: "x", "x and z",
/// "x, y and z"; empty when it is constant-valued.
std::string variables_of(const Expr& e);
std::string variables_of(const ExprVector& v);

}  // namespace zeroset
