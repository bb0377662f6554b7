// JsonWriter: builds one JSON text (RFC 8259) on a single line, for
// machine-readable command output such as `zeroset ray --json` and JSON Lines.
// Numbers keep 17 significant digits, so every double reads back exactly;
// NaN and infinities, which JSON cannot spell, are written as null. Misuse —
// a value where a key is due, an unclosed container — throws std::logic_error.
#pragma once

#include <concepts>
#include <string>
#include <string_view>
#include <vector>

namespace zeroset {

class JsonWriter {
public:
    JsonWriter& begin_object();
    JsonWriter& end_object();
    JsonWriter& begin_array();
    JsonWriter& end_array();
    /// The next member's name; only inside an object, before each value.
    JsonWriter& key(std::string_view name);

    JsonWriter& number(double value);
    template <std::integral I>
        requires(!std::same_as<I, bool>)
    JsonWriter& integer(I value) {
        return raw(std::to_string(value));
    }
    JsonWriter& string(std::string_view value);
    JsonWriter& boolean(bool value);
    JsonWriter& null();

    /// The finished text; throws std::logic_error while a container is open.
    [[nodiscard]] const std::string& text() const;

private:
    enum class Container { Object, Array };
    /// Writes one value's text after any separator it needs.
    JsonWriter& raw(std::string_view text);
    void open(Container c, char bracket);
    void close(Container c, char bracket);
    void before_value();

    std::string text_;
    std::vector<Container> open_;
    bool first_ = true;        // no member or element yet in the innermost container
    bool key_given_ = false;   // inside an object: the value's key has been written
    bool done_ = false;        // a complete top-level value has been written
};

/// `text` as a JSON string literal, quotes included: ", \ and control
/// characters escaped, other UTF-8 passed through.
std::string json_quoted(std::string_view text);

/// `value` with 17 significant digits (reads back exactly), or "null" when
/// it is NaN or infinite.
std::string json_number(double value);

}  // namespace zeroset
