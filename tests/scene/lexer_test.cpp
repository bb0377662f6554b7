// The lexer: token kinds, numbers, strings, comments, locations and the
// lexical errors, each with its exact line and column.
#include "zeroset/scene/lexer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_test_support.hpp"

namespace zeroset {
namespace {

std::vector<Token> lex(std::string_view text) { return tokenize(text, "scene.zs"); }

std::string lex_error(std::string_view text) {
    try {
        lex(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(Lexer, CutsTextIntoTokensWithLocations) {
    const auto tokens = lex("let f = (x - 1.2)^2  # a comment\n  object \"blob\" { }");
    using enum TokenKind;
    const std::vector<TokenKind> kinds{Name,  Name,   Equals, LeftParen, Name,      Minus,      Number, RightParen,
                                       Caret, Number, Name,   String,    LeftBrace, RightBrace, End};
    ASSERT_EQ(tokens.size(), kinds.size());
    for (std::size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(tokens[i].kind, kinds[i]) << "token " << i;
    EXPECT_EQ(tokens[1].text, "f");
    EXPECT_EQ(tokens[6].number, 1.2);
    EXPECT_EQ(tokens[11].text, "blob");  // without the quotes
    EXPECT_EQ(tokens[0].where.line, 1);
    EXPECT_EQ(tokens[0].where.column, 1);
    EXPECT_EQ(tokens[3].where.column, 9);
    EXPECT_EQ(tokens[10].where.line, 2);
    EXPECT_EQ(tokens[10].where.column, 3);
    EXPECT_EQ(tokens[11].where.column, 10);
    EXPECT_EQ(tokens.back().where.line, 2);
    EXPECT_EQ(tokens.back().where.column, 20);
}

TEST(Lexer, ReadsEveryNumberForm) {
    const auto tokens = lex("12 1.5 .5 1. 1e-3 2.5E+4 7e2 0");
    const std::vector<double> values{12, 1.5, 0.5, 1.0, 1e-3, 2.5e4, 700, 0};
    ASSERT_EQ(tokens.size(), values.size() + 1);
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(tokens[i].kind, TokenKind::Number);
        EXPECT_EQ(tokens[i].number, values[i]) << tokens[i].text;
    }
}

TEST(Lexer, MinusIsAnOperatorNotPartOfANumber) {
    const auto tokens = lex("-2");
    ASSERT_EQ(tokens.size(), 3U);
    EXPECT_EQ(tokens[0].kind, TokenKind::Minus);
    EXPECT_EQ(tokens[1].number, 2.0);
}

TEST(Lexer, CommentsRunToTheEndOfTheLine) {
    const auto tokens = lex("# whole line\nx # rest ( of \" line\n# last line without newline");
    ASSERT_EQ(tokens.size(), 2U);
    EXPECT_EQ(tokens[0].text, "x");
    EXPECT_EQ(tokens[0].where.line, 2);
}

TEST(Lexer, ColumnsCountCharactersNotBytes) {
    // "é" is two bytes of UTF-8 but one column; a tab is one column too.
    const auto tokens = lex("object \"blé\" {\tq");
    EXPECT_EQ(tokens[2].where.column, 14);
    EXPECT_EQ(tokens[3].where.column, 16);
}

TEST(Lexer, UnterminatedStringIsReportedAtItsOpeningQuote) {
    EXPECT_EQ(lex_error("include \"other.zs\nobject"),
              "scene.zs:1:9: unterminated string (a string ends with '\"' on the same line)");
    EXPECT_EQ(lex_error("x\n  \"abc"), "scene.zs:2:3: unterminated string (a string ends with '\"' on the same line)");
}

TEST(Lexer, UnexpectedCharacters) {
    EXPECT_EQ(lex_error("let a = 1\nlet b = a @ 2"), "scene.zs:2:11: unexpected character '@'");
    EXPECT_EQ(lex_error("x × y"), "scene.zs:1:3: unexpected character '×'");
    EXPECT_EQ(lex_error("x;"), "scene.zs:1:2: unexpected character ';'");
    EXPECT_EQ(lex_error("a\x01"), "scene.zs:1:2: unexpected control character 0x01");
}

TEST(Lexer, MalformedNumbers) {
    EXPECT_EQ(lex_error("fov 2x"), "scene.zs:1:5: malformed number '2x'");
    EXPECT_EQ(lex_error("  1.2.3"), "scene.zs:1:3: malformed number '1.2.3'");
    EXPECT_EQ(lex_error("3e"), "scene.zs:1:1: malformed number '3e'");
    EXPECT_EQ(lex_error("\n 1e999"), "scene.zs:2:2: number '1e999' is out of range");
}

TEST(Lexer, DescribesTokensForMessages) {
    const auto tokens = lex("foo ) 1.5 \"a.vm\"");
    EXPECT_EQ(describe(tokens[0]), "'foo'");
    EXPECT_EQ(describe(tokens[1]), "')'");
    EXPECT_EQ(describe(tokens[2]), "'1.5'");
    EXPECT_EQ(describe(tokens[3]), "\"a.vm\"");
    EXPECT_EQ(describe(tokens[4]), "end of file");
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Lexer, AByteOrderMarkIsSkipped) {
    const auto tokens = tokenize("\xEF\xBB\xBFobject", "f.zs");
    ASSERT_EQ(tokens.size(), 2u);
    EXPECT_EQ(tokens[0].text, "object");
    EXPECT_EQ(tokens[0].where.column, 1);
}

TEST(Lexer, ALoneCarriageReturnEndsALine) {
    const auto tokens = tokenize("# a comment\rlet\r\nx\ry", "f.zs");
    ASSERT_EQ(tokens.size(), 4u);
    EXPECT_EQ(tokens[0].text, "let");
    EXPECT_EQ(tokens[0].where.line, 2);
    EXPECT_EQ(tokens[1].where.line, 3);
    EXPECT_EQ(tokens[2].where.line, 4);
}

TEST(Lexer, AStringMayNotHoldANulByte) {
    try {
        tokenize(std::string_view("include \"a\0b\"", 14), "f.zs");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "f.zs:1:11: a string may not hold a NUL byte");
    }
}

}  // namespace
}  // namespace zeroset
