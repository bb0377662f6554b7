// TokenStream: one scene file's text and tokens with a cursor over them —
// the peek/accept/expect steps of a recursive-descent parser, and the one
// place that turns a location in this file into a SceneError.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/scene/lexer.hpp"

namespace zeroset {

class TokenStream {
public:
    /// Lexes `text`; throws SceneError on a lexical error.
    TokenStream(std::string file_name, std::string text);
    // Tokens view text_, so the stream stays where it was made.
    TokenStream(const TokenStream&) = delete;
    TokenStream& operator=(const TokenStream&) = delete;

    [[nodiscard]] const std::string& file_name() const { return file_name_; }

    /// The current token (`ahead` tokens further on); End once the text is used up.
    [[nodiscard]] const Token& peek(std::size_t ahead = 0) const {
        return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
    }
    /// Consumes the current token and returns it.
    const Token& next() {
        const Token& token = peek();
        if (pos_ + 1 < tokens_.size()) ++pos_;
        return token;
    }
    [[nodiscard]] bool at(TokenKind kind) const { return peek().kind == kind; }
    /// Consumes the current token if it is of the given kind.
    bool accept(TokenKind kind);
    /// Consumes a token of the given kind, or fails with "expected ')' but found 'x'".
    const Token& expect(TokenKind kind);

    /// Where the cursor is, to come back to with seek() — how the bodies of
    /// loops and shapes are read again.
    [[nodiscard]] std::size_t position() const { return pos_; }
    void seek(std::size_t position) { pos_ = position; }

    /// Throws SceneError at `where` in this file.
    [[noreturn]] void fail(SourceLocation where, const std::string& message) const;
    /// Throws "expected <what> but found <the current token>" at the current token.
    [[noreturn]] void fail_expected(std::string_view what) const;

private:
    std::string file_name_;
    std::string text_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

}  // namespace zeroset
