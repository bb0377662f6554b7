// The built-in functions and the one checker of every call to them.
#include "zeroset/scene/builtin_functions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "zeroset/expr/deform.hpp"
#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

enum class Kind : std::uint8_t {
    Number,    // any number expression (it may depend on x, y, z)
    Constant,  // a constant, finite number
    Vector,    // a constant, finite vector
    Point,     // a vector of number expressions: where a shape is evaluated
};

struct Parameter {
    std::string_view name;
    Kind kind;
};

/// The arguments of a call, checked against its entry's parameters.
class Arguments {
public:
    explicit Arguments(std::span<const Argument> given) : given_(given) {}

    [[nodiscard]] bool has(std::size_t i) const { return i < given_.size(); }
    [[nodiscard]] Expr number(std::size_t i) const { return given_[i].value.number(); }
    [[nodiscard]] double constant(std::size_t i) const { return given_[i].value.constant(); }
    [[nodiscard]] double constant_or(std::size_t i, double otherwise) const { return has(i) ? constant(i) : otherwise; }
    [[nodiscard]] Vec3d vector(std::size_t i) const {
        const ExprVector& v = given_[i].value.vector();
        return {v[0].value(), v[1].value(), v[2].value()};
    }
    /// The point argument i, or (x, y, z) when it is not given.
    [[nodiscard]] ExprPoint point(std::size_t i) const {
        if (!has(i)) return coordinates();
        const ExprVector& v = given_[i].value.vector();
        return {v[0], v[1], v[2]};
    }

private:
    std::span<const Argument> given_;
};

struct Builtin {
    std::string_view name;
    std::vector<Parameter> parameters;
    std::size_t required;  // the first `required` parameters must be given; the others are optional, in order
    bool repeats;          // the last parameter may be given any number of times more (min, max)
    Expr (*build)(const Arguments& args);
    // A function of numbers only has its body twice, made from one generic
    // lambda: over expressions and over constants (fold_builtin_function).
    Expr (*numbers)(std::span<const Expr> args) = nullptr;
    double (*fold)(std::span<const double> args) = nullptr;

    [[nodiscard]] bool accepts(std::size_t count) const {
        return count >= required && (repeats || count <= parameters.size());
    }
    [[nodiscard]] const Parameter& parameter(std::size_t i) const {
        return parameters[std::min(i, parameters.size() - 1)];
    }
    [[nodiscard]] bool numbers_only() const {
        return std::ranges::all_of(parameters, [](const Parameter& p) { return p.kind == Kind::Number; });
    }
    /// "bend(f, along, toward, rate, [lo, hi])", "min(a, b, ...)".
    [[nodiscard]] std::string signature() const {
        std::string text = std::string(name) + "(";
        for (std::size_t i = 0; i < parameters.size(); ++i) {
            if (i > 0) text += ", ";
            if (i == required) text += "[";
            text += parameters[i].name;
        }
        if (required < parameters.size()) text += "]";
        return text + (repeats ? ", ...)" : ")");
    }
};

constexpr Kind N = Kind::Number, C = Kind::Constant, V = Kind::Vector, P = Kind::Point;

/// A function of numbers only, `body` a generic lambda over a span of
/// Exprs or of doubles; `repeats` as in Builtin (min and max).
template <class Body>
Builtin math(std::string_view name, std::vector<std::string_view> parameters, Body body, bool repeats = false) {
    std::vector<Parameter> ps;
    for (const std::string_view p : parameters) ps.push_back({p, N});
    const std::size_t required = ps.size();
    Builtin entry{name, std::move(ps), required, repeats, nullptr};
    entry.numbers = body;
    entry.fold = body;
    return entry;
}

/// a^b as the expression builder makes it, over either kind of number.
Expr power(const Expr& a, const Expr& b) { return pow(a, b); }
double power(double a, double b) { return pow_constant(a, b); }

/// min or max over every argument, left to right.
template <class T, class Combine> T fold_left(std::span<const T> a, Combine combine) {
    T result = a[0];
    for (std::size_t i = 1; i < a.size(); ++i) result = combine(result, a[i]);
    return result;
}

const std::vector<Builtin>& table() {
    using A = const Arguments&;
    static const std::vector<Builtin> builtins{
        // The op table and composites of numbers.
        math("sqrt", {"a"}, [](auto a) { return sqrt(a[0]); }),
        math("abs", {"a"}, [](auto a) { return abs(a[0]); }),
        math("exp", {"a"}, [](auto a) { return exp(a[0]); }),
        math("log", {"a"}, [](auto a) { return log(a[0]); }),
        math("ln", {"a"}, [](auto a) { return log(a[0]); }),
        math("sin", {"a"}, [](auto a) { return sin(a[0]); }),
        math("cos", {"a"}, [](auto a) { return cos(a[0]); }),
        math("tan", {"a"}, [](auto a) { return tan(a[0]); }),
        math("atan", {"a"}, [](auto a) { return atan(a[0]); }),
        math("atan2", {"y", "x"}, [](auto a) { return atan2(a[0], a[1]); }),
        math("floor", {"a"}, [](auto a) { return floor(a[0]); }),
        math("ceil", {"a"}, [](auto a) { return composite::ceil(a[0]); }),
        math("square", {"a"}, [](auto a) { return square(a[0]); }),
        math("pow", {"a", "b"}, [](auto a) { return power(a[0], a[1]); }),
        math("hypot", {"a", "b"}, [](auto a) { return hypot(a[0], a[1]); }),
        math("log_sum_exp", {"a", "b"}, [](auto a) { return log_sum_exp(a[0], a[1]); }),
        math("min", {"a", "b"}, [](auto a) { return fold_left(a, [](auto p, auto q) { return min(p, q); }); }, true),
        math("max", {"a", "b"}, [](auto a) { return fold_left(a, [](auto p, auto q) { return max(p, q); }); }, true),
        math("mod", {"a", "b"}, [](auto a) { return composite::mod(a[0], a[1]); }),
        math("clamp", {"a", "lo", "hi"}, [](auto a) { return composite::clamp(a[0], a[1], a[2]); }),
        math("mix", {"a", "b", "t"}, [](auto a) { return composite::mix(a[0], a[1], a[2]); }),
        math("smoothstep", {"e0", "e1", "a"}, [](auto a) { return composite::smoothstep(a[0], a[1], a[2]); }),
        // Smooth CSG.
        {"smooth_union", {{"a", N}, {"b", N}, {"k", C}}, 3, false,
         [](A a) { return smooth_union(a.number(0), a.number(1), a.constant(2)); }},
        {"smooth_intersection", {{"a", N}, {"b", N}, {"k", C}}, 3, false,
         [](A a) { return smooth_intersection(a.number(0), a.number(1), a.constant(2)); }},
        {"smooth_difference", {{"a", N}, {"b", N}, {"k", C}}, 3, false,
         [](A a) { return smooth_difference(a.number(0), a.number(1), a.constant(2)); }},
        {"algebraic_blend", {{"g", N}, {"h", N}, {"a", C}, {"b", C}}, 4, false,
         [](A a) { return algebraic_blend(a.number(0), a.number(1), a.constant(2), a.constant(3)); }},
        // Distance primitives, at (x, y, z) or at a given point.
        {"sd_sphere", {{"radius", C}, {"point", P}}, 1, false,
         [](A a) { return sd_sphere(a.point(1), a.constant(0)); }},
        {"sd_box", {{"half_size", V}, {"point", P}}, 1, false, [](A a) { return sd_box(a.point(1), a.vector(0)); }},
        {"sd_round_box", {{"half_size", V}, {"radius", C}, {"point", P}}, 2, false,
         [](A a) { return sd_round_box(a.point(2), a.vector(0), a.constant(1)); }},
        {"sd_cylinder", {{"radius", C}, {"half_height", C}, {"point", P}}, 2, false,
         [](A a) { return sd_cylinder(a.point(2), a.constant(0), a.constant(1)); }},
        {"sd_capped_cone", {{"half_height", C}, {"r_bottom", C}, {"r_top", C}, {"point", P}}, 3, false,
         [](A a) { return sd_capped_cone(a.point(3), a.constant(0), a.constant(1), a.constant(2)); }},
        {"sd_capsule", {{"a", V}, {"b", V}, {"radius", C}, {"point", P}}, 3, false,
         [](A a) { return sd_capsule(a.point(3), a.vector(0), a.vector(1), a.constant(2)); }},
        {"sd_torus", {{"R", C}, {"r", C}, {"point", P}}, 2, false,
         [](A a) { return sd_torus(a.point(2), a.constant(0), a.constant(1)); }},
        {"sd_plane", {{"normal", V}, {"offset", C}, {"point", P}}, 2, false,
         [](A a) { return sd_plane(a.point(2), a.vector(0), a.constant(1)); }},
        {"sd_ellipsoid", {{"radii", V}, {"point", P}}, 1, false,
         [](A a) { return sd_ellipsoid(a.point(1), a.vector(0)); }},
        // Deformations of a function f: f∘D⁻¹.
        {"translate", {{"f", N}, {"offset", V}}, 2, false, [](A a) { return translate(a.number(0), a.vector(1)); }},
        {"rotate", {{"f", N}, {"angles", V}}, 2, false, [](A a) { return rotate_degrees(a.number(0), a.vector(1)); }},
        {"rotate", {{"f", N}, {"angle", C}, {"axis", V}}, 3, false,
         [](A a) { return rotate_about(a.number(0), a.vector(2), a.constant(1)); }},
        {"scale", {{"f", N}, {"s", C}}, 2, false, [](A a) { return scale(a.number(0), a.constant(1)); }},
        {"scale", {{"f", N}, {"factors", V}}, 2, false, [](A a) { return scale(a.number(0), a.vector(1)); }},
        {"twist", {{"f", N}, {"axis", V}, {"rate", C}}, 3, false,
         [](A a) { return twist(a.number(0), Twist(a.vector(1), a.constant(2))); }},
        {"taper", {{"f", N}, {"axis", V}, {"rate", C}}, 3, false,
         [](A a) { return taper(a.number(0), Taper(a.vector(1), a.constant(2))); }},
        {"bend", {{"f", N}, {"along", V}, {"toward", V}, {"rate", C}, {"lo", C}, {"hi", C}}, 4, false,
         [](A a) {
             return bend(a.number(0), Bend(a.vector(1), a.vector(2), a.constant(3), a.constant_or(4, -Bend::unlimited),
                                           a.constant_or(5, Bend::unlimited)));
         }},
    };
    return builtins;
}

/// The entries of a name (adjacent in the table), found by hash: calls and
/// `let` ask for every name they read, 10⁵ times in a generated scene.
std::span<const Builtin> entries_named(std::string_view name) {
    static const auto* const index = [] {
        auto* map = new std::unordered_map<std::string_view, std::span<const Builtin>>;
        const std::vector<Builtin>& all = table();
        for (std::size_t i = 0; i < all.size();) {
            std::size_t end = i + 1;
            while (end < all.size() && all[end].name == all[i].name) ++end;
            map->emplace(all[i].name, std::span<const Builtin>(all).subspan(i, end - i));
            i = end;
        }
        return map;
    }();
    const auto found = index->find(name);
    return found == index->end() ? std::span<const Builtin>() : found->second;
}

bool is_vector_kind(Kind k) { return k == Kind::Vector || k == Kind::Point; }

/// "1 argument", "2 or 3 arguments", "4 to 6 arguments", "at least 2 arguments".
std::string counts_accepted(const std::vector<const Builtin*>& overloads) {
    if (overloads.size() == 1 && overloads[0]->repeats)
        return "at least " + std::to_string(overloads[0]->required) + " arguments";
    std::set<std::size_t> counts;
    for (const Builtin* b : overloads)
        for (std::size_t n = b->required; n <= b->parameters.size(); ++n) counts.insert(n);
    const std::size_t lo = *counts.begin(), hi = *counts.rbegin();
    std::string text = std::to_string(lo);
    if (counts.size() == 2) text += " or " + std::to_string(hi);
    if (counts.size() > 2) text += " to " + std::to_string(hi);  // the counts of one entry are contiguous
    return text + (hi == 1 ? " argument" : " arguments");
}

}  // namespace

bool is_builtin_function(std::string_view name) { return !entries_named(name).empty(); }

std::vector<std::string_view> builtin_function_names() {
    std::vector<std::string_view> names;
    for (const Builtin& b : table())
        if (names.empty() || names.back() != b.name) names.push_back(b.name);  // a name's entries are adjacent
    return names;
}

Value call_builtin_function(const TokenStream& in, const Token& name, std::span<const Argument> arguments) {
    std::vector<const Builtin*> overloads;
    for (const Builtin& b : entries_named(name.text)) overloads.push_back(&b);
    const std::string fn(name.text);
    const bool numbers_only = std::ranges::all_of(overloads, [](const Builtin* b) { return b->numbers_only(); });
    std::string hint;
    if (!numbers_only) {
        hint = "; call it as ";
        for (std::size_t i = 0; i < overloads.size(); ++i) hint += (i > 0 ? " or " : "") + overloads[i]->signature();
    }
    if (numbers_only) {
        for (std::size_t i = 0; i < arguments.size(); ++i)
            if (arguments[i].value.is_vector())
                in.fail(arguments[i].where,
                        fn + " takes numbers, but argument " + std::to_string(i + 1) + " is a vector");
    }

    std::vector<const Builtin*> candidates;
    for (const Builtin* b : overloads)
        if (b->accepts(arguments.size())) candidates.push_back(b);
    const std::size_t count = arguments.size();
    if (candidates.empty())
        in.fail(name.where, fn + " takes " + counts_accepted(overloads) + ", but " + std::to_string(count) +
                                (count == 1 ? " was" : " were") + " given" + hint);

    const auto fits = [&](const Builtin* b) {
        for (std::size_t i = 0; i < count; ++i)
            if (arguments[i].value.is_vector() != is_vector_kind(b->parameter(i).kind)) return false;
        return true;
    };
    const auto chosen = std::ranges::find_if(candidates, fits);
    const Builtin& entry = chosen == candidates.end() ? *candidates.front() : **chosen;
    for (std::size_t i = 0; i < count; ++i) {
        const Parameter& p = entry.parameter(i);
        const Value& v = arguments[i].value;
        const std::string subject =
            fn + ": " + std::string(p.name) + " (argument " + std::to_string(i + 1) + ") must be ";
        const auto fail = [&](const std::string& what) { in.fail(arguments[i].where, subject + what + hint); };
        if (v.is_vector() && !is_vector_kind(p.kind)) fail("a number, but it is a vector");
        if (!v.is_vector() && is_vector_kind(p.kind))
            fail(std::string(p.kind == Kind::Point ? "a point" : "a vector") + " (a, b, c), but it is a number");
        if (p.kind == Kind::Constant) {
            if (!v.is_constant()) fail("a constant number, but it depends on " + variables_of(v.number()));
            if (!std::isfinite(v.constant())) fail("finite, but it is " + format_number(v.constant()));
        }
        if (p.kind == Kind::Vector) {
            const ExprVector& e = v.vector();
            for (int k = 0; k < 3; ++k) {
                const Expr& c = e[static_cast<std::size_t>(k)];
                if (!c.is_constant()) fail("a constant vector, but it depends on " + variables_of(e));
                if (!std::isfinite(c.value()))
                    fail("finite, but component " + std::to_string(k + 1) + " is " + format_number(c.value()));
            }
        }
    }
    try {
        if (entry.numbers) {
            std::vector<Expr> numbers;
            for (const Argument& a : arguments) numbers.push_back(a.value.number());
            return entry.numbers(numbers);
        }
        return entry.build(Arguments(arguments));
    } catch (const std::invalid_argument& e) {
        in.fail(name.where, fn + ": " + e.what() + hint);
    }
}

std::optional<double> fold_builtin_function(std::string_view name, std::span<const Argument> arguments) {
    std::array<double, 8> constants{};  // more arguments (a long min or max) are built as an expression
    if (arguments.size() > constants.size()) return std::nullopt;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        if (!arguments[i].value.is_constant()) return std::nullopt;
        constants[i] = arguments[i].value.constant();
    }
    const std::span<const double> values(constants.data(), arguments.size());
    for (const Builtin& b : entries_named(name)) {
        if (b.fold && b.accepts(values.size())) return b.fold(values);
    }
    return std::nullopt;
}

}  // namespace zeroset
