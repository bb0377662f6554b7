// Message wording helpers.
#include "zeroset/scene/wording.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <vector>

namespace zeroset {

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";  // whatever its sign bit
    std::array<char, 32> buffer{};
    char* const first = buffer.data();
    char* const last = first + buffer.size();
    // Whole numbers as integers (100000, not 1e+05); others in their shortest form.
    const bool whole = value == std::floor(value) && std::abs(value) < 1e15;
    const auto result = whole ? std::to_chars(first, last, value, std::chars_format::fixed) : std::to_chars(first, last, value);
    return {first, result.ptr};
}

std::string join_words(std::span<const std::string_view> words, std::string_view conjunction) {
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) text += i + 1 == words.size() ? " " + std::string(conjunction) + " " : ", ";
        text += words[i];
    }
    return text;
}

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

/// Optimal-string-alignment distance: insertions, deletions, substitutions
/// and swaps of neighbours, each 1; letters compared without case.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

}  // namespace

std::optional<std::string_view> closest_name(std::string_view word, std::span<const std::string_view> names) {
    constexpr std::size_t longest = 64;  // a longer word is no misspelling worth the quadratic table
    if (word.size() > longest) return std::nullopt;
    const std::size_t allowed = std::clamp<std::size_t>(word.size() / 3, 1, 3);
    std::optional<std::string_view> best;
    std::size_t best_distance = allowed + 1;
    bool tied = false;
    for (const std::string_view name : names) {
        if (name == word || name.size() > longest) continue;
        const std::size_t distance = edit_distance(word, name);
        if (distance < best_distance) {
            best = name, best_distance = distance, tied = false;
        } else if (distance == best_distance && best && *best != name) {
            tied = true;
        }
    }
    if (tied) return std::nullopt;
    return best;
}

std::string did_you_mean(std::string_view word, std::span<const std::string_view> names) {
    const auto name = closest_name(word, names);
    return name ? "; did you mean '" + std::string(*name) + "'?" : "";
}

std::string unknown_choice(std::string_view what, std::string_view name, std::span<const std::string_view> names) {
    return "unknown " + std::string(what) + " '" + std::string(name) + "' (expected " + join_words(names, "or") + ")" +
           did_you_mean(name, names);
}

std::string line_and_column(SourceLocation where) {
    return "line " + std::to_string(where.line) + ", column " + std::to_string(where.column);
}

}  // namespace zeroset
