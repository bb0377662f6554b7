// Small helpers that word the scene loader's messages the same way
// everywhere: numbers in their shortest exact form, lists as "a, b or c",
// places as "line 3, column 14".
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "zeroset/scene/source_location.hpp"

namespace zeroset {

/// `value` as messages show it: the shortest text that reads back as it
/// ("0.1", "100000", "1e+20", "inf", "nan").
std::string format_number(double value);

/// "line 3, column 14".
std::string line_and_column(SourceLocation where);

/// "a", "a or b", "a, b or c" (with `conjunction` "or"; likewise "and").
std::string join_words(std::span<const std::string_view> words, std::string_view conjunction);

}  // namespace zeroset
