// The expression half of the scene language: numbers, x, y, z, pi, clock, names
// bound by `let`, + - * / ^, function calls, model("file.vm") and vectors
// (a, b, c). Expressions are built into Values while they are read, so an
// unknown name, a wrong argument count or a vector where a number belongs
// is reported at parse time, at the token that caused it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "zeroset/scene/model_library.hpp"
#include "zeroset/scene/scope.hpp"
#include "zeroset/scene/token_stream.hpp"
#include "zeroset/scene/value.hpp"

namespace zeroset {

/// What an expression can refer to besides its own text.
struct ExpressionContext {
    const Scope& scope;
    ModelLibrary& models;
    const std::filesystem::path& base_dir;  // model paths are relative to it
    int max_nesting;                        // SceneLimits::expression_nesting
    double clock = 0.0;                     // the value of `clock`: an animation's time, 0 → 1
};

/// Reads one expression from `in`; stops at the first token that cannot continue it.
Value parse_expression(TokenStream& in, const ExpressionContext& context);

/// Every function the language defines — the built-in table's, the named
/// algebraic surfaces and model — each once.
std::vector<std::string> function_names();

/// Reads the whole of `text` as one expression, with `bindings` visible as
/// names (as if bound by `let`), `clock` reading `clock`, and model paths
/// relative to `base_dir`. Throws SceneError naming `file_name` with the line
/// and column in `text`.
Value evaluate_expression_text(std::string_view text, const std::vector<std::pair<std::string, Value>>& bindings,
                               const std::string& file_name, const std::filesystem::path& base_dir,
                               double clock = 0.0);

/// True for the names the language defines itself (x, y, z, pi, clock and the
/// function names), which `let` may not bind.
bool is_builtin_name(std::string_view name);

}  // namespace zeroset
