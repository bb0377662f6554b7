// JsonWriter: separators and nesting, string escapes, numbers that read back
// exactly, null for what JSON cannot spell, and misuse caught.
#include "zeroset/io/json_writer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace zeroset {
namespace {

TEST(JsonWriter, NestsObjectsAndArraysWithCommas) {
    JsonWriter json;
    json.begin_object();
    json.key("a").integer(1);
    json.key("b").begin_array().integer(2).string("x").null().boolean(true).end_array();
    json.key("c").begin_object().end_object();
    json.key("d").begin_array().begin_array().end_array().begin_object().key("e").boolean(false).end_object().end_array();
    json.end_object();
    EXPECT_EQ(json.text(), R"({"a":1,"b":[2,"x",null,true],"c":{},"d":[[],{"e":false}]})");
}

TEST(JsonWriter, AScalarIsAWholeText) {
    JsonWriter json;
    json.number(0.5);
    EXPECT_EQ(json.text(), "0.5");
}

TEST(JsonWriter, EscapesStrings) {
    EXPECT_EQ(json_quoted("plain"), "\"plain\"");
    EXPECT_EQ(json_quoted("say \"hi\" \\ now"), R"("say \"hi\" \\ now")");
    EXPECT_EQ(json_quoted("a\nb\tc\rd\be\ff"), R"("a\nb\tc\rd\be\ff")");
    EXPECT_EQ(json_quoted(std::string("\x01\x1f", 2)), R"("\u0001\u001f")");
    EXPECT_EQ(json_quoted(std::string("nul\0x", 5)), R"("nul\u0000x")");
    EXPECT_EQ(json_quoted("t₀ ∈ [0, 1]"), "\"t₀ ∈ [0, 1]\"");  // UTF-8 passes through
    EXPECT_EQ(json_quoted("</script>"), "\"</script>\"");
    JsonWriter json;
    json.begin_object().key("we\"ird").string("v").end_object();
    EXPECT_EQ(json.text(), R"({"we\"ird":"v"})");
}

TEST(JsonWriter, NumbersReadBackExactly) {
    for (const double v : {0.981, -4.905, 0.1 + 0.2, 2.99572987604151, 1e-310, 1.7976931348623157e308, -0.0, 1e21, 3.0}) {
        const std::string text = json_number(v);
        EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
        EXPECT_EQ(text.find_first_not_of("0123456789+-.e"), std::string::npos) << text;  // JSON's number syntax
    }
    EXPECT_EQ(json_number(0.981), "0.98099999999999998");  // 17 significant digits
    EXPECT_EQ(json_number(3.0), "3");
    EXPECT_EQ(json_number(1e21), "1e+21");
}

TEST(JsonWriter, NonFiniteNumbersAreNull) {
    EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
    JsonWriter json;
    json.begin_array().number(std::numeric_limits<double>::quiet_NaN()).number(1.0).end_array();
    EXPECT_EQ(json.text(), "[null,1]");
}

TEST(JsonWriter, Integers) {
    JsonWriter json;
    json.begin_array().integer(0).integer(-7).integer(std::numeric_limits<std::uint64_t>::max()).end_array();
    EXPECT_EQ(json.text(), "[0,-7,18446744073709551615]");
}

TEST(JsonWriter, CatchesMisuse) {
    {
        JsonWriter json;
        json.begin_object();
        EXPECT_THROW(json.integer(1), std::logic_error);  // a member needs a key
    }
    {
        JsonWriter json;
        json.begin_array();
        EXPECT_THROW(json.key("k"), std::logic_error);  // no keys in arrays
        EXPECT_THROW(json.end_object(), std::logic_error);
        EXPECT_THROW((void)json.text(), std::logic_error);  // still open
    }
    {
        JsonWriter json;
        json.begin_object().key("k");
        EXPECT_THROW(json.key("again"), std::logic_error);
        EXPECT_THROW(json.end_object(), std::logic_error);  // the key has no value
    }
    {
        JsonWriter json;
        json.null();
        EXPECT_THROW(json.null(), std::logic_error);  // one top-level value only
        EXPECT_THROW(json.end_array(), std::logic_error);
    }
    EXPECT_THROW((void)JsonWriter().text(), std::logic_error);  // nothing written
}

}  // namespace
}  // namespace zeroset
