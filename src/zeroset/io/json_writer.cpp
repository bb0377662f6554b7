// The JSON writer: separators, nesting checks, string escapes and numbers.
#include "zeroset/io/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace zeroset {

std::string json_quoted(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size() + 2);
    out += '"';
    for (const char c : text) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    out += "\\u00";
                    out += hex[static_cast<unsigned char>(c) >> 4];
                    out += hex[static_cast<unsigned char>(c) & 0xF];
                } else {
                    out += c;
                }
        }
    }
    out += '"';
    return out;
}

std::string json_number(double value) {
    if (!std::isfinite(value)) return "null";
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
    return {buffer, result.ptr};
}

JsonWriter& JsonWriter::begin_object() {
    open(Container::Object, '{');
    return *this;
}

JsonWriter& JsonWriter::end_object() {
    close(Container::Object, '}');
    return *this;
}

JsonWriter& JsonWriter::begin_array() {
    open(Container::Array, '[');
    return *this;
}

JsonWriter& JsonWriter::end_array() {
    close(Container::Array, ']');
    return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
    if (open_.empty() || open_.back() != Container::Object) throw std::logic_error("JsonWriter: a key outside an object");
    if (key_given_) throw std::logic_error("JsonWriter: two keys in a row");
    if (!first_) text_ += ',';
    text_ += json_quoted(name);
    text_ += ':';
    key_given_ = true;
    return *this;
}

JsonWriter& JsonWriter::number(double value) { return raw(json_number(value)); }
JsonWriter& JsonWriter::string(std::string_view value) { return raw(json_quoted(value)); }
JsonWriter& JsonWriter::boolean(bool value) { return raw(value ? "true" : "false"); }
JsonWriter& JsonWriter::null() { return raw("null"); }

const std::string& JsonWriter::text() const {
    if (!done_) throw std::logic_error("JsonWriter: the JSON text is incomplete");
    return text_;
}

JsonWriter& JsonWriter::raw(std::string_view text) {
    before_value();
    text_ += text;
    if (open_.empty()) done_ = true;
    return *this;
}

void JsonWriter::open(Container c, char bracket) {
    before_value();
    text_ += bracket;
    open_.push_back(c);
    first_ = true;
}

void JsonWriter::close(Container c, char bracket) {
    if (open_.empty() || open_.back() != c) throw std::logic_error("JsonWriter: closing a container that is not open");
    if (key_given_) throw std::logic_error("JsonWriter: a key without a value");
    text_ += bracket;
    open_.pop_back();
    first_ = false;
    if (open_.empty()) done_ = true;
}

/// Checks that a value may come here and writes the separator it needs.
void JsonWriter::before_value() {
    if (done_) throw std::logic_error("JsonWriter: a second top-level value");
    if (!open_.empty() && open_.back() == Container::Object) {
        if (!key_given_) throw std::logic_error("JsonWriter: an object member without a key");
        key_given_ = false;
    } else if (!open_.empty() && !first_) {
        text_ += ',';
    }
    first_ = false;
}

}  // namespace zeroset
