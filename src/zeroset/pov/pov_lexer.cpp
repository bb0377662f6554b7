// The POV-Ray SDL lexer: one pass over the text, tracking line and column.
#include "zeroset/pov/pov_lexer.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "zeroset/scene/scene_error.hpp"

namespace zeroset::pov {

namespace {

bool is_utf8_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
public:
    Lexer(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    std::vector<PovToken> run() {
        std::vector<PovToken> tokens;
        for (;;) {
            skip_blanks_and_comments();
            PovToken t;
            t.where = here_;
            if (at_end()) {
                tokens.push_back(t);
                return tokens;
            }
            const char c = peek();
            if (is_name_start(c)) {
                t.kind = PovTokenKind::Name;
                t.text = take_name();
            } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
                t.kind = PovTokenKind::Number;
                t.number = take_number(t.where);
            } else if (c == '"') {
                t.kind = PovTokenKind::String;
                t.text = take_string(t.where);
            } else if (c == '#') {
                advance();
                while (!at_end() && (peek() == ' ' || peek() == '\t')) advance();
                if (at_end() || !is_name_start(peek())) fail(t.where, "expected a directive name after '#'");
                t.kind = PovTokenKind::Directive;
                t.text = take_name();
            } else {
                t.kind = PovTokenKind::Symbol;
                t.text = take_symbol(t.where);
            }
            tokens.push_back(std::move(t));
        }
    }

private:
    [[nodiscard]] bool at_end() const { return pos_ >= text_.size(); }
    [[nodiscard]] char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    void advance() {
        const char c = text_[pos_++];
        if (c == '\n') {
            ++here_.line;
            here_.column = 1;
        } else if (!is_utf8_continuation(c)) {
            ++here_.column;
        }
    }
    [[noreturn]] void fail(SourceLocation where, const std::string& message) const {
        throw SceneError(file_, where, message);
    }

    void skip_blanks_and_comments() {
        while (!at_end()) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (!at_end() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                const SourceLocation opened = here_;
                int depth = 0;  // POV-Ray's block comments nest
                do {
                    if (at_end()) fail(opened, "this comment is never closed ('*/')");
                    if (peek() == '/' && peek(1) == '*') {
                        ++depth;
                        advance();
                    } else if (peek() == '*' && peek(1) == '/') {
                        --depth;
                        advance();
                    }
                    advance();
                } while (depth > 0);
            } else {
                return;
            }
        }
    }

    std::string take_name() {
        const std::size_t start = pos_;
        while (!at_end() && is_name_char(peek())) advance();
        return std::string(text_.substr(start, pos_ - start));
    }

    double take_number(SourceLocation where) {
        const std::size_t start = pos_;
        while (is_digit(peek())) advance();
        if (peek() == '.') {
            advance();
            while (is_digit(peek())) advance();
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
            advance();
            if (peek() == '+' || peek() == '-') advance();
            while (is_digit(peek())) advance();
        }
        const std::string_view digits = text_.substr(start, pos_ - start);
        double value = 0.0;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value))
            fail(where, "malformed number '" + std::string(digits) + "'");
        return value;
    }

    std::string take_string(SourceLocation where) {
        advance();  // the opening quote
        std::string s;
        for (;;) {
            if (at_end() || peek() == '\n') fail(where, "this string is never closed (a '\"' on the same line)");
            const char c = peek();
            advance();
            if (c == '"') return s;
            if (c == '\\' && !at_end()) {
                const char e = peek();
                advance();
                switch (e) {
                    case 'n': s += '\n'; break;
                    case 't': s += '\t'; break;
                    default: s += e; break;  // \" \\ and the rest as written
                }
            } else {
                s += c;
            }
        }
    }

    std::string take_symbol(SourceLocation where) {
        const char c = peek();
        const char n = peek(1);
        if ((c == '<' || c == '>' || c == '!') && n == '=') {
            advance();
            advance();
            return std::string{c, n};
        }
        static constexpr std::string_view singles = "{}()[]<>,;+-*/=!?:.&|";
        if (singles.find(c) == std::string_view::npos) {
            std::string shown(1, c);
            if (static_cast<unsigned char>(c) >= 0x80)  // the whole UTF-8 character
                for (std::size_t k = 1; is_utf8_continuation(peek(k)); ++k) shown += peek(k);
            fail(where, "unexpected character '" + shown + "'");
        }
        advance();
        return std::string(1, c);
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t pos_ = 0;
    SourceLocation here_{1, 1};
};

}  // namespace

std::vector<PovToken> tokenize_pov(std::string_view text, const std::string& file_name) {
    return Lexer(text, file_name).run();
}

std::string describe(const PovToken& token) {
    switch (token.kind) {
        case PovTokenKind::End: return "end of file";
        case PovTokenKind::String: return "\"" + token.text + "\"";
        case PovTokenKind::Directive: return "'#" + token.text + "'";
        case PovTokenKind::Number: {
            char buffer[32];
            const auto r = std::to_chars(buffer, buffer + sizeof buffer, token.number);
            return "'" + std::string(buffer, r.ptr) + "'";
        }
        default: return "'" + token.text + "'";
    }
}

}  // namespace zeroset::pov
