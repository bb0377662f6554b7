// POV-Ray's expressions: numbers, vectors (<a, b, c>, up to five
// components), colours (rgb, rgbf, rgbt, rgbft, color red … green …),
// strings, the operators (?: | & comparisons + − * / unary − + !), member
// access (.x, .red, …), the built-in constants and functions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "zeroset/pov/pov_parser.hpp"
#include "zeroset/scene/file_text.hpp"

namespace zeroset::pov {

namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

bool is_color_keyword(std::string_view w) {
    return w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "srgb" || w == "srgbf" || w == "srgbt" ||
           w == "srgbft" || w == "color" || w == "colour";
}

bool is_color_component(std::string_view w) {
    return w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit" || w == "rgb" ||
           w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "srgb" || w == "srgbf" || w == "srgbt" || w == "srgbft";
}

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

PovValue vector_of(std::array<double, 5> v, int size) {
    PovValue value;
    value.kind = PovValue::Kind::Vector;
    value.v = v;
    value.size = size;
    return value;
}

}  // namespace

std::string kind_name(PovValue::Kind kind) {
    switch (kind) {
        case PovValue::Kind::Float: return "a number";
        case PovValue::Kind::Vector: return "a vector";
        case PovValue::Kind::String: return "a string";
        case PovValue::Kind::Object: return "an object";
        case PovValue::Kind::Texture: return "a texture";
        case PovValue::Kind::Transform: return "a transform";
        case PovValue::Kind::Function: return "a function";
        case PovValue::Kind::Other: return "a block zeroset does not read";
    }
    return "a value";
}

bool PovParser::starts_color(const PovToken& t) const { return t.kind == PovTokenKind::Name && is_color_keyword(t.text); }

PovValue PovParser::expression() { return conditional_expression(false); }

PovValue PovParser::conditional_expression(bool in_vector) {
    PovValue c = logical_or(in_vector);
    if (!peek().is_symbol("?")) return c;
    const PovToken at = next();
    if (!c.is_number()) fail(at, "the condition before '?' must be a number");
    PovValue a = conditional_expression(in_vector);
    expect_symbol(":", "in a ? b : c");
    PovValue b = conditional_expression(in_vector);
    return c.v[0] != 0.0 ? a : b;
}

PovValue PovParser::logical_or(bool in_vector) {
    PovValue a = logical_and(in_vector);
    while (peek().is_symbol("|")) {
        const PovToken at = next();
        const PovValue b = logical_and(in_vector);
        if (!a.is_number() || !b.is_number()) fail(at, "'|' takes numbers");
        a = PovValue::number(a.v[0] != 0.0 || b.v[0] != 0.0 ? 1.0 : 0.0);
    }
    return a;
}

PovValue PovParser::logical_and(bool in_vector) {
    PovValue a = comparison(in_vector);
    while (peek().is_symbol("&")) {
        const PovToken at = next();
        const PovValue b = comparison(in_vector);
        if (!a.is_number() || !b.is_number()) fail(at, "'&' takes numbers");
        a = PovValue::number(a.v[0] != 0.0 && b.v[0] != 0.0 ? 1.0 : 0.0);
    }
    return a;
}

PovValue PovParser::comparison(bool in_vector) {
    PovValue a = additive(in_vector);
    for (;;) {
        const PovToken& t = peek();
        const bool angle = t.is_symbol("<") || t.is_symbol(">");
        // Only numbers compare: after a vector, '<' opens the next vector
        // (POV-Ray lets the comma before it be left out: box { <a> <b> }).
        if (!(t.is_symbol("=") || t.is_symbol("!=") || t.is_symbol("<=") || t.is_symbol(">=") || angle) ||
            (angle && (in_vector || !a.is_number())) || (t.is_symbol("<") && opens_vector()))
            return a;
        const PovToken at = next();
        const PovValue b = additive(in_vector);
        if (!a.is_number() || !b.is_number()) fail(at, "'" + at.text + "' compares numbers");
        const double x = a.v[0], y = b.v[0];
        bool r = false;
        if (at.text == "=") r = x == y;
        else if (at.text == "!=") r = x != y;
        else if (at.text == "<") r = x < y;
        else if (at.text == "<=") r = x <= y;
        else if (at.text == ">") r = x > y;
        else r = x >= y;
        a = PovValue::number(r ? 1.0 : 0.0);
    }
}

bool PovParser::opens_vector() {
    // After a number, "< a, b, … >" is the next value with its comma left
    // out (sphere_sweep { … 0.1 <1, 0, 0> … }); "a < b" is a comparison. A
    // vector has a comma and then a '>' before anything closes around it.
    int depth = 0;
    bool comma = false;
    for (std::size_t k = 1; k < 256; ++k) {
        const PovToken& t = peek_raw(k);
        if (t.kind == PovTokenKind::End || t.kind == PovTokenKind::Directive || t.is_symbol(";")) return false;
        if (t.is_symbol("(") || t.is_symbol("[") || t.is_symbol("{")) ++depth;
        if (t.is_symbol(")") || t.is_symbol("]") || t.is_symbol("}")) {
            if (depth == 0) return false;
            --depth;
        }
        if (depth == 0 && t.is_symbol(",")) comma = true;
        if (depth == 0 && t.is_symbol(">")) return comma;
    }
    return false;
}

PovValue PovParser::promoted(const PovValue& value, int size, const PovToken& at) const {
    if (!value.is_numeric()) fail(at, "expected a number or vector, not " + kind_name(value.kind));
    if (value.is_number()) {
        std::array<double, 5> v{};
        for (int i = 0; i < size; ++i) v[static_cast<std::size_t>(i)] = value.v[0];
        return vector_of(v, size);
    }
    PovValue r = value;
    r.size = std::max(r.size, size);
    return r;
}

PovValue PovParser::arithmetic(const PovValue& a, const PovValue& b, char op, const PovToken& at) const {
    if (op == '+' && a.kind == PovValue::Kind::String && b.kind == PovValue::Kind::String)
        fail(at, "strings are joined with concat(…), not '+'");
    if (!a.is_numeric() || !b.is_numeric())
        fail(at, std::string("'") + op + "' takes numbers and vectors, not " + kind_name(a.is_numeric() ? b.kind : a.kind));
    const auto apply = [op](double x, double y) {
        switch (op) {
            case '+': return x + y;
            case '-': return x - y;
            case '*': return x * y;
            default: return x / y;
        }
    };
    if (a.is_number() && b.is_number()) return PovValue::number(apply(a.v[0], b.v[0]));
    const int size = std::max(a.is_number() ? 0 : a.size, b.is_number() ? 0 : b.size);
    const PovValue x = promoted(a, size, at), y = promoted(b, size, at);
    std::array<double, 5> v{};
    for (int i = 0; i < size; ++i) v[static_cast<std::size_t>(i)] = apply(x.v[static_cast<std::size_t>(i)], y.v[static_cast<std::size_t>(i)]);
    return vector_of(v, size);
}

PovValue PovParser::additive(bool in_vector) {
    PovValue a = multiplicative(in_vector);
    while (peek().is_symbol("+") || peek().is_symbol("-")) {
        const PovToken at = next();
        a = arithmetic(a, multiplicative(in_vector), at.text[0], at);
    }
    return a;
}

PovValue PovParser::multiplicative(bool in_vector) {
    PovValue a = unary(in_vector);
    while (peek().is_symbol("*") || peek().is_symbol("/")) {
        const PovToken at = next();
        a = arithmetic(a, unary(in_vector), at.text[0], at);
    }
    return a;
}

PovValue PovParser::unary(bool in_vector) {
    const Nesting nesting(*this);
    const PovToken& t = peek();
    if (t.is_symbol("-") || t.is_symbol("+") || t.is_symbol("!")) {
        const PovToken at = next();
        PovValue v = unary(in_vector);
        if (!v.is_numeric()) fail(at, "'" + at.text + "' takes a number or vector");
        if (at.text == "!") {
            if (!v.is_number()) fail(at, "'!' takes a number");
            return PovValue::number(v.v[0] == 0.0 ? 1.0 : 0.0);
        }
        if (at.text == "-")
            for (double& c : v.v) c = -c;
        return v;
    }
    return postfix(in_vector);
}

PovValue PovParser::postfix(bool in_vector) {
    PovValue v = primary(in_vector);
    while (peek().is_symbol(".")) {
        const PovToken at = next();
        const PovToken member = expect_name("a component after '.' (x, y, z, t, u, v, red, green, blue, filter, transmit, gray)");
        if (!v.is_numeric()) fail(at, "'." + member.text + "' needs a vector");
        const PovValue w = promoted(v, 5, at);
        const std::string& m = member.text;
        std::size_t i = 0;
        if (m == "x" || m == "u" || m == "red") i = 0;
        else if (m == "y" || m == "v" || m == "green") i = 1;
        else if (m == "z" || m == "blue") i = 2;
        else if (m == "t" || m == "filter") i = 3;
        else if (m == "transmit") i = 4;
        else if (m == "gray" || m == "grey") {
            v = PovValue::number(0.297 * w.v[0] + 0.589 * w.v[1] + 0.114 * w.v[2]);
            continue;
        } else {
            fail(member, "unknown component '." + m + "'");
        }
        v = PovValue::number(w.v[i]);
    }
    return v;
}

PovValue PovParser::color_value(const PovToken& keyword) {
    std::array<double, 5> c{};
    const auto take = [&](const std::string& word) {
        if (word == "red" || word == "green" || word == "blue" || word == "filter" || word == "transmit") {
            const double x = number(word);
            const std::size_t i = word == "red" ? 0 : word == "green" ? 1 : word == "blue" ? 2 : word == "filter" ? 3 : 4;
            c[i] = x;
            return;
        }
        // rgb, rgbf, rgbt, rgbft and their srgb forms: a vector, or a number for every component.
        const bool s = word[0] == 's';
        const std::string_view kind = std::string_view(word).substr(s ? 1 : 0);
        const PovToken at = peek();
        const PovValue v = additive(false);
        const int size = kind == "rgb" ? 3 : kind == "rgbft" ? 5 : 4;
        const PovValue w = promoted(v, 5, at);
        if (!v.is_number() && v.size < size && !(kind == "rgb" && v.size >= 3))
            fail(at, word + " needs " + std::to_string(size) + " components");
        c = {w.v[0], w.v[1], w.v[2], 0.0, 0.0};
        if (s)
            for (std::size_t i = 0; i < 3; ++i) c[i] = srgb_to_linear(c[i]);
        if (kind == "rgbf") c[3] = w.v[3];
        if (kind == "rgbt") c[4] = w.v[3];
        if (kind == "rgbft") c[3] = w.v[3], c[4] = w.v[4];
    };
    if (keyword.text == "color" || keyword.text == "colour") {
        const PovToken& t = peek();
        if (!(t.kind == PovTokenKind::Name && is_color_component(t.text))) {
            const PovToken at = peek();
            const PovValue base = additive(false);
            const PovValue w = promoted(base, 5, at);
            c = w.v;
            if (!base.is_number() && base.size < 3) fail(at, "a colour needs at least 3 components");
        }
    } else {
        take(keyword.text);
    }
    while (peek().kind == PovTokenKind::Name && is_color_component(peek().text)) take(next().text);
    return vector_of(c, 5);
}

PovValue PovParser::primary(bool in_vector) {
    (void)in_vector;
    const PovToken t = next();
    switch (t.kind) {
        case PovTokenKind::Number: return PovValue::number(t.number);
        case PovTokenKind::String: {
            PovValue s;
            s.kind = PovValue::Kind::String;
            s.text = t.text;
            return s;
        }
        case PovTokenKind::Symbol:
            if (t.text == "(") {
                PovValue v = expression();
                expect_symbol(")", "to close '('");
                return v;
            }
            if (t.text == "<") {
                std::array<double, 5> v{};
                int size = 0;
                // POV-Ray lets the commas be left out: <1 0 0>.
                do {
                    const PovToken at = peek();
                    const PovValue c = conditional_expression(true);
                    if (!c.is_number()) fail(at, "a vector's components must be numbers");
                    if (size == 5) fail(at, "a vector has at most 5 components");
                    v[static_cast<std::size_t>(size++)] = c.v[0];
                    accept_symbol(",");
                } while (!peek().is_symbol(">") && peek().kind != PovTokenKind::End);
                expect_symbol(">", "to close the vector");
                if (size < 2) fail(t, "a vector needs at least 2 components");
                return vector_of(v, size);
            }
            break;
        case PovTokenKind::Name: {
            if (const PovValue* found = use(t.text)) {
                // A copy: looking at the next token may end a macro's
                // frame and free the local it named.
                const PovValue v = *found;
                if (v.kind == PovValue::Kind::Function && peek().is_symbol("(")) {
                    const std::vector<Expr> args = function_arguments();
                    const Expr r = apply(*v.function, args, t);
                    if (!r.is_constant()) fail(t, "the function " + t.text + " does not give a number here");
                    return PovValue::number(r.value());
                }
                return v;
            }
            if (starts_color(t)) return color_value(t);
            const std::string& w = t.text;
            if (w == "x") return PovValue::vector({1, 0, 0});
            if (w == "y") return PovValue::vector({0, 1, 0});
            if (w == "z") return PovValue::vector({0, 0, 1});
            if (w == "t") return vector_of({0, 0, 0, 1, 0}, 4);
            if (w == "u") return vector_of({1, 0, 0, 0, 0}, 2);
            if (w == "v") return vector_of({0, 1, 0, 0, 0}, 2);
            if (w == "pi") return PovValue::number(std::numbers::pi);
            if (w == "tau") return PovValue::number(2.0 * std::numbers::pi);
            if (w == "true" || w == "yes" || w == "on") return PovValue::number(1.0);
            if (w == "false" || w == "no" || w == "off") return PovValue::number(0.0);
            if (w == "clock") return PovValue::number(options_.clock);
            if (w == "clock_delta") return PovValue::number(1.0);
            if (w == "clock_on") return PovValue::number(0.0);
            if (w == "initial_clock") return PovValue::number(0.0);
            if (w == "final_clock") return PovValue::number(1.0);
            if (w == "frame_number" || w == "initial_frame" || w == "final_frame") return PovValue::number(w == "final_frame" ? 1.0 : 0.0);
            if (w == "image_width") return PovValue::number(options_.width);
            if (w == "image_height") return PovValue::number(options_.height);
            if (w == "version") return PovValue::number(3.7);
            if (peek().is_symbol("(")) return call_builtin(t);
            fail(t, "unknown name '" + w + "' (not declared, and not a built-in value or function)");
        }
        default: break;
    }
    fail(t, "expected a value but found " + describe(t));
}

PovValue PovParser::call_builtin(const PovToken& name) {
    const std::string& f = name.text;
    if (f == "defined") {  // defined(Name): the name is not evaluated
        expect_symbol("(", "after defined");
        const PovToken n = peek_raw(0);
        if (n.kind != PovTokenKind::Name) fail_expected("a name");
        ++frames_.back().pos;
        expect_symbol(")", "to close defined(…)");
        return PovValue::number(lookup(n.text) != nullptr || macros_.contains(n.text) ? 1.0 : 0.0);
    }
    expect_symbol("(", "after " + f);
    std::vector<PovValue> args;
    std::vector<PovToken> places;
    if (!accept_symbol(")")) {
        do {
            places.push_back(peek());
            args.push_back(expression());
        } while (accept_symbol(","));
        expect_symbol(")", "to close the arguments of " + f);
    }
    const auto need = [&](std::size_t least, std::size_t most) {
        if (args.size() < least || args.size() > most)
            fail(name, f + " takes " + (least == most ? std::to_string(least) : std::to_string(least) + " to " + std::to_string(most)) +
                           " arguments, not " + std::to_string(args.size()));
    };
    const auto num = [&](std::size_t i) {
        if (!args[i].is_number()) fail(places[i], f + ": argument " + std::to_string(i + 1) + " must be a number");
        return args[i].v[0];
    };
    const auto vec = [&](std::size_t i) {
        if (!args[i].is_numeric()) fail(places[i], f + ": argument " + std::to_string(i + 1) + " must be a vector");
        return args[i].xyz();
    };
    const auto str = [&](std::size_t i) {
        if (args[i].kind != PovValue::Kind::String) fail(places[i], f + ": argument " + std::to_string(i + 1) + " must be a string");
        return args[i].text;
    };
    using Unary = double (*)(double);
    static const std::map<std::string, Unary, std::less<>> unary{
        {"abs", [](double a) { return std::abs(a); }},     {"acos", [](double a) { return std::acos(a); }},
        {"acosh", [](double a) { return std::acosh(a); }}, {"asin", [](double a) { return std::asin(a); }},
        {"asinh", [](double a) { return std::asinh(a); }}, {"atanh", [](double a) { return std::atanh(a); }},
        {"ceil", [](double a) { return std::ceil(a); }},   {"cos", [](double a) { return std::cos(a); }},
        {"cosh", [](double a) { return std::cosh(a); }},   {"exp", [](double a) { return std::exp(a); }},
        {"floor", [](double a) { return std::floor(a); }}, {"int", [](double a) { return std::trunc(a); }},
        {"ln", [](double a) { return std::log(a); }},      {"log", [](double a) { return std::log10(a); }},
        {"sin", [](double a) { return std::sin(a); }},     {"sinh", [](double a) { return std::sinh(a); }},
        {"sqrt", [](double a) { return std::sqrt(a); }},   {"tan", [](double a) { return std::tan(a); }},
        {"tanh", [](double a) { return std::tanh(a); }},
        {"radians", [](double a) { return a / degrees_per_radian; }},
        {"degrees", [](double a) { return a * degrees_per_radian; }},
    };
    if (const auto u = unary.find(f); u != unary.end()) {
        need(1, 1);
        return PovValue::number(u->second(num(0)));
    }
    if (f == "atan") {
        need(1, 1);
        return PovValue::number(std::atan(num(0)));
    }
    if (f == "atan2" || f == "pow" || f == "mod" || f == "div") {
        need(2, 2);
        const double a = num(0), b = num(1);
        if (f == "atan2") return PovValue::number(std::atan2(a, b));
        if (f == "pow") return PovValue::number(std::pow(a, b));
        if (f == "mod") return PovValue::number(std::fmod(a, b));
        return PovValue::number(std::trunc(a / b));
    }
    if (f == "min" || f == "max") {
        need(1, 64);
        double r = num(0);
        for (std::size_t i = 1; i < args.size(); ++i) r = f == "min" ? std::min(r, num(i)) : std::max(r, num(i));
        return PovValue::number(r);
    }
    if (f == "select") {
        need(3, 4);
        const double a = num(0);
        if (args.size() == 3) return a < 0.0 ? args[1] : args[2];
        return a < 0.0 ? args[1] : a == 0.0 ? args[2] : args[3];
    }
    if (f == "vlength") {
        need(1, 1);
        return PovValue::number(length(vec(0)));
    }
    if (f == "vnormalize") {
        need(1, 1);
        return PovValue::vector(normalize(vec(0)));
    }
    if (f == "vdot") {
        need(2, 2);
        return PovValue::number(dot(vec(0), vec(1)));
    }
    if (f == "vcross") {
        need(2, 2);
        return PovValue::vector(cross(vec(0), vec(1)));
    }
    if (f == "vrotate") {
        need(2, 2);
        return PovValue::vector(Mat4::rotate_xyz_degrees(vec(1)).transform_vector(vec(0)));
    }
    if (f == "vaxis_rotate") {
        need(3, 3);
        return PovValue::vector(Mat4::rotate_degrees(normalize(vec(1)), num(2)).transform_vector(vec(0)));
    }
    if (f == "strlen") {
        need(1, 1);
        return PovValue::number(static_cast<double>(str(0).size()));
    }
    if (f == "str" || f == "concat" || f == "chr" || f == "substr" || f == "strupr" || f == "strlwr") {
        PovValue s;
        s.kind = PovValue::Kind::String;
        if (f == "str") {  // str(value, length, precision): a negative length pads with zeros
            need(3, 3);
            const double length = std::clamp(num(1), -64.0, 64.0), precision = std::clamp(num(2), -1.0, 32.0);
            char buffer[160];
            const int width = static_cast<int>(std::abs(length));
            const int digits = precision < 0.0 ? 6 : static_cast<int>(precision);
            std::snprintf(buffer, sizeof buffer, length < 0.0 ? "%0*.*f" : "%*.*f", width, digits, num(0));
            s.text = buffer;
        } else if (f == "concat") {
            for (std::size_t i = 0; i < args.size(); ++i) s.text += str(i);
        } else if (f == "chr") {
            need(1, 1);
            s.text = std::string(1, static_cast<char>(num(0)));
        } else if (f == "substr") {
            need(3, 3);
            const std::string whole = str(0);
            const auto from = static_cast<std::size_t>(std::max(1.0, num(1)) - 1);
            s.text = from < whole.size() ? whole.substr(from, static_cast<std::size_t>(std::max(0.0, num(2)))) : "";
        } else {
            need(1, 1);
            s.text = str(0);
            for (char& c : s.text) c = static_cast<char>(f == "strupr" ? std::toupper(static_cast<unsigned char>(c)) : std::tolower(static_cast<unsigned char>(c)));
        }
        return s;
    }
    if (f == "val") {
        need(1, 1);
        return PovValue::number(std::atof(str(0).c_str()));
    }
    if (f == "file_exists") {
        need(1, 1);
        return PovValue::number(regular_file_exists(resolve_path(files_[frames_.back().file]->dir, str(0))) ? 1.0 : 0.0);
    }
    fail(name, "the function " + f + "(…) is not supported");
}

double PovParser::number(std::string_view what) {
    const PovToken at = peek();
    const PovValue v = expression();
    if (!v.is_number()) fail(at, std::string(what) + " must be a number, not " + kind_name(v.kind));
    if (!std::isfinite(v.v[0])) fail(at, std::string(what) + " must be finite, but it is " + std::to_string(v.v[0]));
    return v.v[0];
}

Vec3d PovParser::vector3(std::string_view what) {
    const PovToken at = peek();
    const PovValue v = expression();
    if (!v.is_numeric()) fail(at, std::string(what) + " must be a vector, not " + kind_name(v.kind));
    if (v.kind == PovValue::Kind::Vector && v.size < 3) fail(at, std::string(what) + " needs 3 components");
    const Vec3d r = v.xyz();
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z)) fail(at, std::string(what) + " must be finite");
    return r;
}

std::array<double, 5> PovParser::color(std::string_view what) {
    const PovToken at = peek();
    const PovValue v = starts_color(at) ? color_value(next()) : expression();
    if (!v.is_numeric()) fail(at, std::string(what) + " must be a colour, not " + kind_name(v.kind));
    if (!std::all_of(v.v.begin(), v.v.end(), [](double c) { return std::isfinite(c); }))
        fail(at, std::string(what) + " must be finite");
    if (v.is_number()) return {v.v[0], v.v[0], v.v[0], 0.0, 0.0};
    if (v.size < 3) fail(at, std::string(what) + " needs at least 3 components");
    return v.v;
}

std::string PovParser::string_value(std::string_view what) {
    // A plain "literal" is taken raw: looking past it for an operator would
    // carry out the directive after it (the next #declare after an
    // #include, say) before this one's.
    if (const PovToken& raw = peek_raw(0); raw.kind == PovTokenKind::String) {
        ++frames_.back().pos;
        return raw.text;
    }
    const PovToken at = peek();
    const PovValue v = expression();
    if (v.kind != PovValue::Kind::String) fail(at, std::string(what) + " must be a string, not " + kind_name(v.kind));
    return v.text;
}

}  // namespace zeroset::pov
