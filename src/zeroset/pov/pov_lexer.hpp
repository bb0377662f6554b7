// The tokens of POV-Ray's scene description language (SDL), for the
// importer (pov_reader.hpp): names, numbers, "strings", directives (#declare,
// #if, …) and punctuation; whitespace and comments — `// …` and nesting
// `/* … */` — are dropped. Every token keeps its place in its file for
// file:line:column messages.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/scene/source_location.hpp"

namespace zeroset::pov {

enum class PovTokenKind {
    Name,       // [A-Za-z_][A-Za-z0-9_]*
    Number,     // 12, 1.5, .5, 1e-3
    String,     // "text", with its escapes resolved
    Directive,  // #declare, #if, …: text is the word after '#'
    Symbol,     // punctuation: { } ( ) [ ] < > , ; + - * / = ! ? : . & | and <= >= !=
    End,        // after the last token
};

struct PovToken {
    PovTokenKind kind = PovTokenKind::End;
    std::string text;     // the name, the string's content, the directive's word or the symbol
    double number = 0.0;  // a Number's value
    SourceLocation where;
    std::uint32_t file = 0;  // which of the reader's files it is in (set by the reader)

    [[nodiscard]] bool is(PovTokenKind k, std::string_view t) const { return kind == k && text == t; }
    [[nodiscard]] bool is_symbol(std::string_view t) const { return is(PovTokenKind::Symbol, t); }
    [[nodiscard]] bool is_name(std::string_view t) const { return is(PovTokenKind::Name, t); }
};

/// The tokens of `text`, ending with one End token. Throws SceneError (naming
/// `file_name`) at a character that starts no token, an unterminated string
/// or comment, or a malformed number.
std::vector<PovToken> tokenize_pov(std::string_view text, const std::string& file_name);

/// A token as messages show it: 'sphere', '{', '1.5', "colors.inc", '#declare' or `end of file`.
std::string describe(const PovToken& token);

}  // namespace zeroset::pov
