// Message wording helpers.
#include "zeroset/scene/wording.hpp"

#include <array>
#include <charconv>
#include <cmath>

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

std::string line_and_column(SourceLocation where) {
    return "line " + std::to_string(where.line) + ", column " + std::to_string(where.column);
}

}  // namespace zeroset
