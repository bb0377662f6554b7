// POV-Ray's user functions, `function [(a, b, …)] { body }`, as zeroset
// expressions: a body is read again at each call with its parameters bound
// to the call's arguments (expressions of x, y, z), so functions calling
// functions compose into one expression. POV-Ray's internal functions
// (functions.inc's `function { internal(n) }`) are known by the name they
// were declared as; those with a closed form are built from it.
#include <cmath>
#include <numbers>

#include "zeroset/expr/functions.hpp"
#include "zeroset/expr/shapes.hpp"
#include "zeroset/expr/substitute.hpp"
#include "zeroset/pov/pov_parser.hpp"

namespace zeroset::pov {

namespace {

/// Functions calling functions deeper than this are an error (recursion).
constexpr std::size_t max_function_depth = 64;

}  // namespace

std::shared_ptr<const PovFunction> PovParser::function_definition(const PovToken& keyword) {
    auto f = std::make_shared<PovFunction>();
    if (accept_symbol("(")) {
        if (!accept_symbol(")")) {
            do {
                const PovToken p = peek_raw(0);
                if (p.kind != PovTokenKind::Name) fail_expected("a parameter name");
                ++frames_.back().pos;
                f->parameters.push_back(p.text);
            } while (accept_symbol(","));
            expect_symbol(")", "to close the function's parameters");
        }
    } else {
        f->parameters = {"x", "y", "z"};
    }
    expect_symbol("{", "to open the function's body");
    Frame& frame = frames_.back();
    const std::vector<PovToken>& tokens = files_[frame.file]->tokens;
    f->file = frame.file;
    f->begin = frame.pos;
    int depth = 1;
    while (frame.pos < frame.end && tokens[frame.pos].kind != PovTokenKind::End) {
        const PovToken& t = tokens[frame.pos++];
        if (t.is_symbol("{")) ++depth;
        if (t.is_symbol("}") && --depth == 0) break;
    }
    if (depth != 0) fail(keyword, "the function's body is not closed by '}'");
    f->end = frame.pos - 1;
    const std::size_t n = f->end - f->begin;
    if (n == 4 && tokens[f->begin].is_name("internal") && tokens[f->begin + 1].is_symbol("(") &&
        tokens[f->begin + 2].kind == PovTokenKind::Number && tokens[f->begin + 3].is_symbol(")"))
        f->internal = static_cast<int>(tokens[f->begin + 2].number);
    else if (n > 0 && (tokens[f->begin].is_name("pattern") || tokens[f->begin].is_name("pigment") ||
                       tokens[f->begin].is_name("spline") || tokens[f->begin].kind == PovTokenKind::String))
        f->unsupported = "a function of a " +
                         (tokens[f->begin].kind == PovTokenKind::String ? std::string("string") : tokens[f->begin].text);
    else if (f->parameters.size() <= 3)
        f->body = read_body(*f);
    return f;
}

std::optional<Expr> PovParser::read_body(const PovFunction& function) {
    const std::array<Expr, 3> stand_ins{var_x(), var_y(), var_z()};
    std::map<std::string, Expr> bound;
    for (std::size_t i = 0; i < function.parameters.size(); ++i) bound[function.parameters[i]] = stand_ins[i];
    const std::size_t frames = frames_.size(), scopes = function_scopes_.size(), nesting = static_cast<std::size_t>(nesting_);
    function_scopes_.push_back(std::move(bound));
    frames_.push_back({Frame::Kind::Function, function.file, function.begin, function.end, scopes_.size(), blocks_.size()});
    std::optional<Expr> body;
    try {
        body = function_expression();
        if (frames_.back().pos != function.end) body.reset();
    } catch (const SceneError&) {  // said again where it is called
        body.reset();
    }
    frames_.resize(frames);
    function_scopes_.resize(scopes);
    nesting_ = static_cast<int>(nesting);
    return body;
}

Expr PovParser::apply(const PovFunction& function, const std::vector<Expr>& arguments, const PovToken& at) {
    if (!function.unsupported.empty()) fail(at, function.unsupported + " is not supported");
    if (function.internal) return internal_function(function, arguments, at);
    if (arguments.size() != function.parameters.size())
        fail(at, "the function takes " + std::to_string(function.parameters.size()) + " arguments, not " +
                     std::to_string(arguments.size()));
    if (function.body) {
        ExprPoint p{Expr(0.0), Expr(0.0), Expr(0.0)};
        for (std::size_t i = 0; i < arguments.size(); ++i) p[static_cast<int>(i)] = arguments[i];
        return substitute(*function.body, p);
    }
    if (function_scopes_.size() >= max_function_depth) fail(at, "functions call each other more than 64 deep");
    std::map<std::string, Expr> bound;
    for (std::size_t i = 0; i < arguments.size(); ++i) bound[function.parameters[i]] = arguments[i];
    function_scopes_.push_back(std::move(bound));
    frames_.push_back({Frame::Kind::Function, function.file, function.begin, function.end, scopes_.size(), blocks_.size()});
    const Expr body = function_expression();
    if (frames_.back().pos != function.end) fail_expected("an operator or the end of the function");
    frames_.pop_back();
    function_scopes_.pop_back();
    return body;
}

std::vector<Expr> PovParser::function_arguments() {
    std::vector<Expr> args;
    expect_symbol("(", "before the arguments");
    if (accept_symbol(")")) return args;
    do {
        if (function_scopes_.empty()) {  // called from a number's expression: the arguments are numbers
            const PovToken at = peek();
            const PovValue v = expression();
            if (!v.is_number()) fail(at, "a function's arguments must be numbers");
            args.emplace_back(v.v[0]);
        } else {
            args.push_back(function_expression());
        }
    } while (accept_symbol(","));
    expect_symbol(")", "to close the arguments");
    return args;
}

Expr PovParser::function_expression() {
    const Expr c = function_or();
    if (!peek().is_symbol("?")) return c;
    const PovToken at = next();
    const Expr a = function_expression();
    expect_symbol(":", "in a ? b : c");
    const Expr b = function_expression();
    if (!c.is_constant()) fail(at, "a condition (?:) on x, y or z is not supported in a function (zeroset's functions are continuous)");
    return c.value() != 0.0 ? a : b;
}

Expr PovParser::function_or() {
    Expr a = function_and();
    while (peek().is_symbol("|")) {
        const PovToken at = next();
        const Expr b = function_and();
        if (!a.is_constant() || !b.is_constant()) fail(at, "'|' on x, y or z is not supported in a function");
        a = Expr(a.value() != 0.0 || b.value() != 0.0 ? 1.0 : 0.0);
    }
    return a;
}

Expr PovParser::function_and() {
    Expr a = function_comparison();
    while (peek().is_symbol("&")) {
        const PovToken at = next();
        const Expr b = function_comparison();
        if (!a.is_constant() || !b.is_constant()) fail(at, "'&' on x, y or z is not supported in a function");
        a = Expr(a.value() != 0.0 && b.value() != 0.0 ? 1.0 : 0.0);
    }
    return a;
}

Expr PovParser::function_comparison() {
    Expr a = function_additive();
    for (;;) {
        const PovToken& t = peek();
        if (!(t.is_symbol("=") || t.is_symbol("!=") || t.is_symbol("<") || t.is_symbol("<=") || t.is_symbol(">") ||
              t.is_symbol(">=")))
            return a;
        const PovToken at = next();
        const Expr b = function_additive();
        if (!a.is_constant() || !b.is_constant())
            fail(at, "a comparison on x, y or z is not supported in a function (zeroset's functions are continuous)");
        const double x = a.value(), y = b.value();
        const std::string& op = at.text;
        const bool r = op == "=" ? x == y : op == "!=" ? x != y : op == "<" ? x < y : op == "<=" ? x <= y : op == ">" ? x > y : x >= y;
        a = Expr(r ? 1.0 : 0.0);
    }
}

Expr PovParser::function_additive() {
    Expr a = function_multiplicative();
    while (peek().is_symbol("+") || peek().is_symbol("-")) {
        const bool plus = next().text == "+";
        const Expr b = function_multiplicative();
        a = plus ? a + b : a - b;
    }
    return a;
}

Expr PovParser::function_multiplicative() {
    Expr a = function_unary();
    while (peek().is_symbol("*") || peek().is_symbol("/")) {
        const bool times = next().text == "*";
        const Expr b = function_unary();
        a = times ? a * b : a / b;
    }
    return a;
}

Expr PovParser::function_unary() {
    const Nesting nesting(*this);
    if (accept_symbol("-")) return -function_unary();
    if (accept_symbol("+")) return function_unary();
    if (peek().is_symbol("!")) {
        const PovToken at = next();
        const Expr a = function_unary();
        if (!a.is_constant()) fail(at, "'!' on x, y or z is not supported in a function");
        return Expr(a.value() == 0.0 ? 1.0 : 0.0);
    }
    return function_primary();
}

Expr PovParser::function_primary() {
    const PovToken t = next();
    if (t.kind == PovTokenKind::Number) return Expr(t.number);
    if (t.is_symbol("(")) {
        const Expr e = function_expression();
        expect_symbol(")", "to close '('");
        return e;
    }
    if (t.kind != PovTokenKind::Name) fail(t, "expected a value in the function but found " + describe(t));
    const std::string& w = t.text;
    for (auto scope = function_scopes_.rbegin(); scope != function_scopes_.rend(); ++scope)
        if (const auto found = scope->find(w); found != scope->end()) return found->second;
    if (const PovValue* found = use(w)) {
        const PovValue v = *found;  // a copy: the next token may end the frame that holds it
        if (v.kind == PovValue::Kind::Function) return apply(*v.function, function_arguments(), t);
        if (v.is_number()) return Expr(v.v[0]);
        if (v.is_numeric() && peek().is_symbol(".")) {  // a vector's component
            next();
            const PovToken m = expect_name("a component (x, y, z)");
            const std::size_t i = m.text == "x" ? 0 : m.text == "y" ? 1 : m.text == "z" ? 2 : 3;
            if (i == 3) fail(m, "a function takes only .x, .y or .z of a vector");
            return Expr(v.v[i]);
        }
        fail(t, "'" + w + "' is " + kind_name(v.kind) + ", not a number a function can use");
    }
    if (w == "pi") return Expr(std::numbers::pi);
    if (w == "true" || w == "yes" || w == "on") return Expr(1.0);
    if (w == "false" || w == "no" || w == "off") return Expr(0.0);
    if (w == "clock") return Expr(options_.clock);
    if (!peek().is_symbol("(")) fail(t, "unknown name '" + w + "' in the function");
    const std::vector<Expr> a = function_arguments();
    const auto need = [&](std::size_t n) {
        if (a.size() != n) fail(t, w + " takes " + std::to_string(n) + " arguments, not " + std::to_string(a.size()));
    };
    if (w == "abs") return need(1), abs(a[0]);
    if (w == "sqrt") return need(1), sqrt(a[0]);
    if (w == "exp") return need(1), exp(a[0]);
    if (w == "ln") return need(1), log(a[0]);
    if (w == "log") return need(1), log(a[0]) / Expr(std::numbers::ln10);
    if (w == "sin") return need(1), sin(a[0]);
    if (w == "cos") return need(1), cos(a[0]);
    if (w == "tan") return need(1), tan(a[0]);
    if (w == "atan") return need(1), atan(a[0]);
    if (w == "atan2") return need(2), atan2(a[0], a[1]);
    if (w == "asin") return need(1), atan2(a[0], sqrt(Expr(1.0) - square(a[0])));
    if (w == "acos") return need(1), atan2(sqrt(Expr(1.0) - square(a[0])), a[0]);
    if (w == "sinh") return need(1), (exp(a[0]) - exp(-a[0])) / Expr(2.0);
    if (w == "cosh") return need(1), (exp(a[0]) + exp(-a[0])) / Expr(2.0);
    if (w == "tanh") return need(1), Expr(1.0) - Expr(2.0) / (exp(Expr(2.0) * a[0]) + Expr(1.0));
    if (w == "floor") return need(1), floor(a[0]);
    if (w == "ceil") return need(1), ceil(a[0]);
    if (w == "pow") return need(2), pow(a[0], a[1]);
    if (w == "radians") return need(1), a[0] * Expr(std::numbers::pi / 180.0);
    if (w == "degrees") return need(1), a[0] * Expr(180.0 / std::numbers::pi);
    if (w == "min" || w == "max") {
        if (a.empty()) fail(t, w + " takes at least one argument");
        Expr r = a[0];
        for (std::size_t i = 1; i < a.size(); ++i) r = w == "min" ? min(r, a[i]) : max(r, a[i]);
        return r;
    }
    fail(t, "the function " + w + "(…) is not supported in a function body (zeroset's functions are continuous: "
            "int, mod, select and comparisons have no counterpart)");
}

Expr PovParser::internal_function(const PovFunction& function, const std::vector<Expr>& a, const PovToken& at) {
    const std::string& name = function.name;
    const auto need = [&](std::size_t n) {
        if (a.size() != n) fail(at, name + " takes " + std::to_string(n) + " arguments, not " + std::to_string(a.size()));
    };
    if (name == "f_sphere") {  // (x, y, z, radius)
        need(4);
        return sqrt(square(a[0]) + square(a[1]) + square(a[2])) - a[3];
    }
    if (name == "f_torus") {  // (x, y, z, major radius, minor radius), around y
        need(5);
        return hypot(hypot(a[0], a[2]) - a[3], a[1]) - a[4];
    }
    if (name == "f_noise3d") {
        need(3);
        warn(at, "f_noise3d (POV-Ray's Perlin noise) is not supported; rendered as its mean, 0.5");
        return Expr(0.5);
    }
    fail(at, "POV-Ray's internal function " + (name.empty() ? "#" + std::to_string(*function.internal) : name) +
                 " is not supported (zeroset knows f_sphere, f_torus and f_noise3d)");
}

}  // namespace zeroset::pov
