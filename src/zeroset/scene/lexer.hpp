// The scene language's tokens, and the lexer that cuts a scene's text into
// them: names, numbers, "strings" and punctuation; whitespace and `#`
// comments are dropped. Every token keeps its location for error messages.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "zeroset/scene/source_location.hpp"

namespace zeroset {

enum class TokenKind {
    Name,    // [A-Za-z_][A-Za-z0-9_]*
    Number,  // 12, 1.5, .5, 1., 1e-3, 2.5E+4
    String,  // "text" on one line, no escapes
    LeftParen,
    RightParen,
    LeftBrace,
    RightBrace,
    Comma,
    Equals,
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    End,  // after the last token
};

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // as written (a string without its quotes); views the source text
    double number = 0.0;    // the value of a Number
    SourceLocation where;
};

/// The tokens of `text`, ending with one End token. Throws SceneError (naming
/// `file_name`) at a character that starts no token, an unterminated string
/// or a malformed or out-of-range number.
std::vector<Token> tokenize(std::string_view text, const std::string& file_name);

/// A token as messages show it: 'x', '(', '1.5', "bear.vm" or `end of file`.
std::string describe(const Token& token);

/// What a token of this kind is called in "expected …" messages: ')', a name, …
std::string_view token_kind_name(TokenKind kind);

}  // namespace zeroset
