// The ray suite's text format: tab-separated, one ray per line, '#' comments
// (see tests/data/README.md). Doubles are written so they read back exactly.
#include "support/ray_suite.hpp"

#include <array>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace zeroset::test {

namespace {

constexpr std::size_t column_count = 15;
constexpr std::string_view none = "none";

/// The shortest text that reads back as exactly v.
std::string shortest(double v) {
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
    return {buffer.data(), result.ptr};
}

std::string digits17(std::optional<double> v) {
    if (!v) return std::string(none);
    std::array<char, 32> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "%.17g", *v);
    return buffer.data();
}

std::string digits3(double v) {
    std::array<char, 32> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "%.3g", v);
    return buffer.data();
}

double parse_double(std::string_view text, const std::string& where) {
    double v = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), v);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size())
        throw std::runtime_error(where + ": '" + std::string(text) + "' is not a number");
    return v;
}

std::optional<double> parse_optional(std::string_view text, const std::string& where) {
    if (text == none) return std::nullopt;
    return parse_double(text, where);
}

std::vector<std::string_view> split_tabs(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t tab = line.find('\t', start);
        fields.push_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
        if (tab == std::string_view::npos) return fields;
        start = tab + 1;
    }
}

SuiteRay parse_row(std::string_view line, const std::string& where) {
    const auto f = split_tabs(line);
    if (f.size() != column_count)
        throw std::runtime_error(where + ": " + std::to_string(f.size()) + " columns, expected " +
                                 std::to_string(column_count));
    const auto number = [&](std::size_t i) { return parse_double(f[i], where); };
    SuiteRay r;
    r.surface = std::string(f[0]);
    r.ray = {{number(1), number(2), number(3)}, {number(4), number(5), number(6)}};
    r.span = {number(7), number(8)};
    r.t_ref = parse_optional(f[9], where);
    const auto kind = ref_kind_from_name(f[10]);
    if (!kind) throw std::runtime_error(where + ": unknown kind '" + std::string(f[10]) + "'");
    r.kind = *kind;
    if (r.t_ref.has_value() != (r.kind != RefKind::None)) throw std::runtime_error(where + ": t_ref and kind disagree");
    r.scale = number(11);
    r.ray_class = std::string(f[12]);
    r.slope = number(13);
    r.t_next = parse_optional(f[14], where);
    return r;
}

}  // namespace

std::string_view ref_kind_name(RefKind kind) {
    switch (kind) {
        case RefKind::Simple: return "simple";
        case RefKind::Multiple: return "multiple";
        case RefKind::Tangent: return "tangent";
        case RefKind::None: return "none";
    }
    return "?";
}

std::optional<RefKind> ref_kind_from_name(std::string_view name) {
    for (const RefKind k : {RefKind::Simple, RefKind::Multiple, RefKind::Tangent, RefKind::None})
        if (ref_kind_name(k) == name) return k;
    return std::nullopt;
}

std::string_view ray_suite_columns() {
    return "#surface\tox\toy\toz\tdx\tdy\tdz\tt0\tt1\tt_ref\tkind\tscale\tclass\tslope\tt_next";
}

std::string format_suite_ray(const SuiteRay& r) {
    std::string line = r.surface;
    for (const double v :
         {r.ray.origin.x, r.ray.origin.y, r.ray.origin.z, r.ray.dir.x, r.ray.dir.y, r.ray.dir.z, r.span.t0, r.span.t1})
        line += '\t' + shortest(v);
    line += '\t' + digits17(r.t_ref);
    line += '\t' + std::string(ref_kind_name(r.kind));
    line += '\t' + shortest(r.scale);
    line += '\t' + r.ray_class;
    line += '\t' + digits3(r.slope);
    line += '\t' + digits17(r.t_next);
    return line;
}

std::vector<SuiteRay> load_ray_suite(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open the ray suite " + path.string());
    std::vector<SuiteRay> rays;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty() || line.front() == '#') continue;
        rays.push_back(parse_row(line, path.string() + ":" + std::to_string(number)));
    }
    return rays;
}

}  // namespace zeroset::test
