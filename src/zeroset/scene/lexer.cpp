// The scene lexer: one pass over the text, tracking line and column.
#include "zeroset/scene/lexer.hpp"

#include <array>
#include <charconv>
#include <cstdio>

#include "zeroset/scene/scene_error.hpp"

namespace zeroset {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }
bool is_utf8_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }

class Lexer {
public:
    Lexer(std::string_view text, const std::string& file_name) : text_(text), file_name_(file_name) {
        if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // a UTF-8 byte-order mark says nothing here
    }

    std::vector<Token> run() {
        std::vector<Token> tokens;
        for (skip_space_and_comments(); !at_end(); skip_space_and_comments()) tokens.push_back(token());
        tokens.push_back({TokenKind::End, {}, 0.0, here_});
        return tokens;
    }

private:
    [[nodiscard]] bool at_end() const { return pos_ >= text_.size(); }
    [[nodiscard]] char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }

    /// A line ends at "\n", "\r\n" or a lone "\r".
    [[nodiscard]] bool at_line_end() const { return peek() == '\n' || peek() == '\r'; }

    void advance() {
        const char c = text_[pos_++];
        if (c == '\n' || (c == '\r' && peek() != '\n')) {
            ++here_.line;
            here_.column = 1;
        } else if (!is_utf8_continuation(c)) {
            ++here_.column;
        }
    }

    [[noreturn]] void fail(SourceLocation where, const std::string& message) const {
        throw SceneError(file_name_, where, message);
    }

    void skip_space_and_comments() {
        while (!at_end()) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                advance();
            } else if (c == '#') {
                while (!at_end() && !at_line_end()) advance();
            } else {
                return;
            }
        }
    }

    Token token() {
        const char c = peek();
        if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return number();
        if (is_name_start(c)) return name();
        if (c == '"') return string();
        return punctuation();
    }

    std::string_view take_while(bool (*accept)(char)) {
        const std::size_t start = pos_;
        while (!at_end() && accept(peek())) advance();
        return text_.substr(start, pos_ - start);
    }

    Token number() {
        const SourceLocation where = here_;
        const std::size_t start = pos_;
        take_while(is_digit);
        if (peek() == '.') {
            advance();
            take_while(is_digit);
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
            advance();
            if (!is_digit(peek())) advance();
            take_while(is_digit);
        }
        // A number glued to letters, digits or another point ("2x", "1.2.3", "3e") is a typo, not two tokens.
        if (is_name_char(peek()) || peek() == '.') {
            take_while([](char ch) { return is_name_char(ch) || ch == '.'; });
            fail(where, "malformed number '" + std::string(text_.substr(start, pos_ - start)) + "'");
        }
        const std::string_view text = text_.substr(start, pos_ - start);
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size())
            fail(where, "number '" + std::string(text) + "' is out of range");
        return {TokenKind::Number, text, value, where};
    }

    Token name() {
        const SourceLocation where = here_;
        return {TokenKind::Name, take_while(is_name_char), 0.0, where};
    }

    Token string() {
        const SourceLocation where = here_;
        advance();  // the opening quote
        const std::size_t start = pos_;
        while (!at_end() && peek() != '"' && !at_line_end()) {
            if (peek() == '\0') fail(here_, "a string may not hold a NUL byte");
            advance();
        }
        if (peek() != '"') fail(where, "unterminated string (a string ends with '\"' on the same line)");
        const std::string_view text = text_.substr(start, pos_ - start);
        advance();  // the closing quote
        return {TokenKind::String, text, 0.0, where};
    }

    Token punctuation() {
        const SourceLocation where = here_;
        const std::size_t start = pos_;
        TokenKind kind = TokenKind::End;
        switch (peek()) {
            case '(': kind = TokenKind::LeftParen; break;
            case ')': kind = TokenKind::RightParen; break;
            case '{': kind = TokenKind::LeftBrace; break;
            case '}': kind = TokenKind::RightBrace; break;
            case ',': kind = TokenKind::Comma; break;
            case '=': kind = TokenKind::Equals; break;
            case '+': kind = TokenKind::Plus; break;
            case '-': kind = TokenKind::Minus; break;
            case '*': kind = TokenKind::Star; break;
            case '/': kind = TokenKind::Slash; break;
            case '^': kind = TokenKind::Caret; break;
            default: unexpected_character();
        }
        advance();
        return {kind, text_.substr(start, 1), 0.0, where};
    }

    [[noreturn]] void unexpected_character() {
        const SourceLocation where = here_;
        const auto byte = static_cast<unsigned char>(peek());
        if (byte < 0x20 || byte == 0x7F) {
            std::array<char, 8> hex{};
            std::snprintf(hex.data(), hex.size(), "0x%02X", static_cast<unsigned>(byte));
            fail(where, "unexpected control character " + std::string(hex.data()));
        }
        // Quote the whole character, however many UTF-8 bytes it takes.
        const std::size_t start = pos_;
        advance();
        while (!at_end() && is_utf8_continuation(peek())) advance();
        fail(where, "unexpected character '" + std::string(text_.substr(start, pos_ - start)) + "'");
    }

    std::string_view text_;
    const std::string& file_name_;
    std::size_t pos_ = 0;
    SourceLocation here_{1, 1};
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, const std::string& file_name) {
    return Lexer(text, file_name).run();
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::End: return "end of file";
        case TokenKind::String: return "\"" + std::string(token.text) + "\"";
        default: return "'" + std::string(token.text) + "'";
    }
}

std::string_view token_kind_name(TokenKind kind) {
    switch (kind) {
        case TokenKind::Name: return "a name";
        case TokenKind::Number: return "a number";
        case TokenKind::String: return "a string in quotes";
        case TokenKind::LeftParen: return "'('";
        case TokenKind::RightParen: return "')'";
        case TokenKind::LeftBrace: return "'{'";
        case TokenKind::RightBrace: return "'}'";
        case TokenKind::Comma: return "','";
        case TokenKind::Equals: return "'='";
        case TokenKind::Plus: return "'+'";
        case TokenKind::Minus: return "'-'";
        case TokenKind::Star: return "'*'";
        case TokenKind::Slash: return "'/'";
        case TokenKind::Caret: return "'^'";
        case TokenKind::End: return "end of file";
    }
    return "?";
}

}  // namespace zeroset
