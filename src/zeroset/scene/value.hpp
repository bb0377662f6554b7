// Value: what a scene expression evaluates to — a number (an Expr in x, y, z;
// constant folding makes a constant-valued one a single Const) or a vector
// (a, b, c) of three numbers. Each key of a block says which it needs.
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
    Value(Expr number) : value_(std::move(number)) {}        // NOLINT: a number is a Value
    Value(ExprVector vector) : value_(std::move(vector)) {}  // NOLINT: so is a vector

    [[nodiscard]] bool is_vector() const { return std::holds_alternative<ExprVector>(value_); }
    [[nodiscard]] const Expr& number() const { return std::get<Expr>(value_); }
    [[nodiscard]] const ExprVector& vector() const { return std::get<ExprVector>(value_); }
    /// "a number" or "a vector", for messages.
    [[nodiscard]] std::string_view kind_name() const { return is_vector() ? "a vector" : "a number"; }

private:
    std::variant<Expr, ExprVector> value_;
};

/// The coordinates an expression depends on, for messages: "x", "x and z",
/// "x, y and z"; empty when it is constant-valued.
std::string variables_of(const Expr& e);
std::string variables_of(const ExprVector& v);

}  // namespace zeroset
