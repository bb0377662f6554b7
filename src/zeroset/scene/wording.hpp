// Small helpers that word the scene loader's messages the same way
// everywhere: numbers in their shortest exact form, lists as "a, b or c",
// places as "line 3, column 14", and "did you mean …" for a misspelt name
// (the scene language's and the command line's alike).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/scene/source_location.hpp"

namespace zeroset {

/// `value` as messages show it: the shortest text that reads back as it
/// ("0.1", "100000", "1e+20", "inf", "nan").
std::string format_number(double value);

/// "line 3, column 14".
std::string line_and_column(SourceLocation where);

/// "a", "a or b", "a, b or c" (with `conjunction` "or"; likewise "and").
std::string join_words(std::span<const std::string_view> words, std::string_view conjunction);

/// The one name of `names` that `word` most plausibly misspells: the
/// nearest in edit distance (a swap of neighbours counts once, case is
/// ignored), if it is within a third of the word's length (at least 1, at
/// most 3) and no other name is as near. Nothing otherwise.
std::optional<std::string_view> closest_name(std::string_view word, std::span<const std::string_view> names);

/// "; did you mean 'color'?" for closest_name(word, names), else "".
std::string did_you_mean(std::string_view word, std::span<const std::string_view> names);

/// "unknown method 'intervall' (expected auto, sphere, … or bisection); did
/// you mean 'interval'?" — for the scene language and the command line alike.
std::string unknown_choice(std::string_view what, std::string_view name, std::span<const std::string_view> names);

/// The names of a family's members (methods, solvers…), in its order.
template <class Member, class NameOf>
std::vector<std::string_view> names_of(std::span<const Member> members, NameOf name_of) {
    std::vector<std::string_view> names;
    for (const Member& m : members) names.push_back(name_of(m));
    return names;
}

}  // namespace zeroset
