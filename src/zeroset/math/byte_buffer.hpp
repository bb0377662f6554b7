// Numbers and texts packed into one byte string and read back, for what
// travels between the processes of a distributed render (scene files, tile
// results). Values are copied as their bytes: every process runs the same
// build on the same kind of machine, so no byte order or layout is changed.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace zeroset {

class ByteWriter {
public:
    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void put_text(std::string_view text) {
        put<std::uint64_t>(text.size());
        bytes_.append(text);
    }
    template <class T, class Allocator>
    void put_vector(const std::vector<T, Allocator>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put<std::uint64_t>(values.size());
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    [[nodiscard]] std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

/// Reads what a ByteWriter wrote, in the same order; throws
/// std::runtime_error("… are damaged") rather than read past the end.
class ByteReader {
public:
    ByteReader(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}

    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    std::string get_text() {
        const auto size = get<std::uint64_t>();
        need(size);
        std::string text(bytes_.substr(at_, size));
        at_ += size;
        return text;
    }
    template <class T, class Vector = std::vector<T>>
    Vector get_vector() {
        const auto count = get<std::uint64_t>();
        if (count > (bytes_.size() - at_) / sizeof(T)) damaged();
        Vector values(count);
        std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return values;
    }
    /// Throws unless every byte was read.
    void expect_end() const {
        if (at_ != bytes_.size()) damaged();
    }

private:
    void need(std::uint64_t n) const {
        if (n > bytes_.size() - at_) damaged();
    }
    [[noreturn]] void damaged() const { throw std::runtime_error(std::string(what_) + " are damaged"); }

    std::string_view bytes_;
    const char* what_;
    std::size_t at_ = 0;
};

}  // namespace zeroset
