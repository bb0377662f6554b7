// Option parsing for the zeroset program.
#include "options.hpp"

#include <algorithm>
#include <charconv>

namespace zeroset::cli {

namespace {
bool contains(const std::vector<std::string>& list, const std::string& s) {
    return std::find(list.begin(), list.end(), s) != list.end();
}
}  // namespace

Options::Options(const std::vector<std::string>& args, const std::vector<std::string>& valued,
                 const std::vector<std::string>& flags) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        if (arg.size() < 2 || arg[0] != '-' || arg == "--") {
            positional_.push_back(arg);
            continue;
        }
        std::optional<std::string> inline_value;
        if (const auto eq = arg.find('='); arg.starts_with("--") && eq != std::string::npos) {
            inline_value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
        }
        if (contains(flags, arg)) {
            if (inline_value) throw UsageError("option " + arg + " takes no value");
            flags_.push_back(arg);
        } else if (contains(valued, arg)) {
            if (!inline_value && i + 1 >= args.size()) throw UsageError("option " + arg + " needs a value");
            const std::string value = inline_value ? *inline_value : args[++i];
            if (std::any_of(values_.begin(), values_.end(), [&](const auto& v) { return v.first == arg; }))
                throw UsageError("option " + arg + " is given twice");
            values_.emplace_back(arg, value);
        } else {
            std::vector<std::string_view> known(valued.begin(), valued.end());
            known.insert(known.end(), flags.begin(), flags.end());
            throw UsageError("unknown option " + arg + did_you_mean(arg, known));
        }
    }
}

bool Options::has(const std::string& name) const { return contains(flags_, name); }

std::optional<std::string> Options::value(const std::string& name) const {
    for (const auto& [key, v] : values_)
        if (key == name) return v;
    return std::nullopt;
}

namespace {

template <class Number>
std::optional<Number> whole_number(const std::optional<std::string>& text, const std::string& name) {
    if (!text) return std::nullopt;
    Number result = 0;
    const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), result);
    if (error != std::errc() || end != text->data() + text->size())
        throw UsageError("option " + name + " needs a whole number, got '" + *text + "'");
    return result;
}

}  // namespace

std::optional<int> Options::integer(const std::string& name) const { return whole_number<int>(value(name), name); }

std::optional<std::uint64_t> Options::count(const std::string& name) const {
    return whole_number<std::uint64_t>(value(name), name);
}

}  // namespace zeroset::cli
