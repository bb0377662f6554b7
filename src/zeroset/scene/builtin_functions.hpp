// The scene language's table of built-in functions (docs/scene-language.md,
// docs/shapes.md): the maths of the op table, the composite functions, the
// distance primitives with an optional point to evaluate them at, the smooth
// blends and the deformations. Each entry names its parameters and what each
// must be — any number expression, a constant number, a constant vector, or
// the point — so that one checker words every wrong call the same way, at
// the call or at the offending argument. A name may have several entries
// (rotate(f, angles) and rotate(f, angle, axis)): the call picks the first
// whose argument count and kinds fit. The named algebraic surfaces have a
// table of their own (algebraic_surfaces.hpp).
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "zeroset/scene/token_stream.hpp"
#include "zeroset/scene/value.hpp"

namespace zeroset {

/// One argument as written: its value and where its text starts.
struct Argument {
    Value value;
    SourceLocation where;
};

/// True when `name` is a built-in function of this table.
bool is_builtin_function(std::string_view name);

/// The table's names, each once, in the table's order.
std::vector<std::string_view> builtin_function_names();

/// Calls the built-in function `name` (is_builtin_function(name)) with the
/// arguments, or fails through `in` — at the name for a wrong argument count
/// or parameter values that make no sense, at an argument for a wrong kind or
/// a non-constant where a constant is needed.
Value call_builtin_function(const TokenStream& in, const Token& name, std::span<const Argument> arguments);

/// The function of numbers `name` at constant arguments, computed in doubles
/// with the same steps as building the call and folding it to a constant;
/// nullopt when an argument is not a constant number, or `name` is not a
/// function of numbers alone, or does not take this many arguments (the
/// caller then builds the call, which words any error).
std::optional<double> fold_builtin_function(std::string_view name, std::span<const Argument> arguments);

}  // namespace zeroset
