// A small command-line option reader: `--name value`, `--name=value`,
// `-o value`, flags, and positional arguments, with clear usage errors.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/scene/wording.hpp"

namespace zeroset::cli {

/// A mistake in how the program was called (exit status 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Options {
public:
    /// `valued` lists the options that take a value (e.g. "--width", "-o").
    Options(const std::vector<std::string>& args, const std::vector<std::string>& valued,
            const std::vector<std::string>& flags);

    [[nodiscard]] bool has(const std::string& name) const;
    [[nodiscard]] std::optional<std::string> value(const std::string& name) const;
    /// The option's value as an integer, or nothing when absent.
    [[nodiscard]] std::optional<int> integer(const std::string& name) const;
    /// The option's value as a count (a whole number ≥ 0 up to 2^64 − 1), or nothing when absent.
    [[nodiscard]] std::optional<std::uint64_t> count(const std::string& name) const;
    [[nodiscard]] const std::vector<std::string>& positional() const { return positional_; }

    /// The option's value as one of a family (a method, a solver…), or
    /// nothing when absent; another name is a UsageError that lists the
    /// family and suggests the nearest.
    template <class Member, class NameOf>
    [[nodiscard]] std::optional<Member> choice(const std::string& name, std::string_view what,
                                               std::span<const Member> members, NameOf name_of) const {
        const auto given = value(name);
        if (!given) return std::nullopt;
        for (const Member& m : members)
            if (name_of(m) == *given) return m;
        throw UsageError(unknown_choice(what, *given, names_of(members, name_of)));
    }

private:
    std::vector<std::pair<std::string, std::string>> values_;
    std::vector<std::string> flags_;
    std::vector<std::string> positional_;
};

}  // namespace zeroset::cli
