// Recursive descent over the expression grammar (docs/scene-language.md):
//
//   expression := term (('+' | '-') term)*
//   term       := unary (('*' | '/') unary)*
//   unary      := ('-' | '+') unary | power
//   power      := primary ('^' unary)?          right-associative, above unary minus
//   primary    := NUMBER | NAME | NAME '(' arguments ')' | '(' expression ')'
//               | '(' expression ',' expression ',' expression ')'
#include "zeroset/scene/expression_parser.hpp"

#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/scene/algebraic_surfaces.hpp"
#include "zeroset/scene/builtin_functions.hpp"
#include "zeroset/scene/constant_value.hpp"
#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_limits.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

constexpr std::string_view model_function = "model";

/// The names that stand for values: x, y, z and pi.
/// The animation clock: a constant the scene is read with (render --frames).
constexpr std::string_view clock_name = "clock";

std::optional<Expr> builtin_value(std::string_view name) {
    if (name == "x") return var_x();
    if (name == "y") return var_y();
    if (name == "z") return var_z();
    if (name == "pi") return Expr(std::numbers::pi);
    return std::nullopt;
}

std::string plural(std::size_t n, std::string_view word) {
    return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

class ExpressionParser {
public:
    ExpressionParser(TokenStream& in, const ExpressionContext& context) : in_(in), context_(context) {}

    Value expression() {
        Value left = term();
        while (in_.at(TokenKind::Plus) || in_.at(TokenKind::Minus)) {
            const Token& op = in_.next();
            left = combine(op, left, term());
        }
        return left;
    }

private:
    /// Counts one level of nesting for as long as it lives.
    class Nesting {
    public:
        Nesting(ExpressionParser& parser, const Token& at) : parser_(parser) {
            // Past the limit the text is rejected rather than overflowing the stack.
            const int limit = parser_.context_.max_nesting;
            if (++parser_.depth_ > limit)
                parser_.in_.fail(at.where, "expression nested too deeply (more than " + std::to_string(limit) +
                                               " levels)");
        }
        ~Nesting() { --parser_.depth_; }
        Nesting(const Nesting&) = delete;
        Nesting& operator=(const Nesting&) = delete;

    private:
        ExpressionParser& parser_;
    };

    Value term() {
        Value left = unary();
        while (in_.at(TokenKind::Star) || in_.at(TokenKind::Slash)) {
            const Token& op = in_.next();
            left = combine(op, left, unary());
        }
        return left;
    }

    Value unary() {
        if (!in_.at(TokenKind::Minus) && !in_.at(TokenKind::Plus)) return power();
        const Token& sign = in_.next();
        const Nesting nesting(*this, sign);
        Value operand = unary();
        if (sign.kind == TokenKind::Plus) return operand;
        if (operand.is_constant()) return -operand.constant();
        if (!operand.is_vector()) return -operand.number();
        const ExprVector& v = operand.vector();
        return ExprVector{-v[0], -v[1], -v[2]};
    }

    Value power() {
        Value base = primary();
        if (!in_.at(TokenKind::Caret)) return base;
        const Token& op = in_.next();
        const Nesting nesting(*this, op);
        return combine(op, base, unary());
    }

    Value primary() {
        const Token& token = in_.peek();
        switch (token.kind) {
            case TokenKind::Number: in_.next(); return token.number;
            case TokenKind::Name:
                in_.next();
                return in_.at(TokenKind::LeftParen) ? call(token) : name(token);
            case TokenKind::LeftParen: return parenthesised();
            default: in_.fail_expected("an expression");
        }
    }

    Value name(const Token& token) {
        const std::string_view text = token.text;
        if (const auto value = builtin_value(text)) return *value;
        if (text == clock_name) return context_.clock;
        if (const Binding* binding = context_.scope.find(text)) return binding->value;
        if (is_builtin_function(text) || text == model_function || find_algebraic_surface(text))
            in_.fail(token.where, "'" + std::string(text) + "' is a function: call it as " + std::string(text) + "(...)");
        std::vector<std::string_view> names = context_.scope.visible_names();
        names.insert(names.end(), {"x", "y", "z", "pi", clock_name});
        in_.fail(token.where, "unknown identifier '" + std::string(text) + "'" + did_you_mean(text, names));
    }

    /// A parenthesised expression, or a vector (a, b, c).
    Value parenthesised() {
        const Token& open = in_.next();
        const Nesting nesting(*this, open);
        std::vector<Value> items;
        std::vector<SourceLocation> starts;
        do {
            starts.push_back(in_.peek().where);
            items.push_back(expression());
        } while (in_.accept(TokenKind::Comma));
        if (!in_.accept(TokenKind::RightParen)) in_.fail_expected(items.size() == 1 ? "')'" : "',' or ')'");
        if (items.size() == 1) return items.front();
        if (items.size() != 3)
            in_.fail(open.where, "a vector has 3 components, but this one has " + std::to_string(items.size()));
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (items[i].is_vector())
                in_.fail(starts[i], "a vector's components must be numbers, but component " + std::to_string(i + 1) +
                                        " is a vector");
        }
        return ExprVector{items[0].number(), items[1].number(), items[2].number()};
    }

    Value call(const Token& name) {
        if (name.text == model_function) return model(name);
        if (const AlgebraicSurface* surface = find_algebraic_surface(name.text)) return algebraic(name, *surface);
        if (!is_builtin_function(name.text)) {
            const bool is_value = context_.scope.find(name.text) || builtin_value(name.text) || name.text == clock_name;
            if (is_value) in_.fail(name.where, "'" + std::string(name.text) + "' is not a function");
            const std::vector<std::string> functions = function_names();
            const std::vector<std::string_view> views(functions.begin(), functions.end());
            in_.fail(name.where, "unknown function '" + std::string(name.text) + "'" + did_you_mean(name.text, views) +
                                     " (the functions are " + join_words(views, "and") + ")");
        }
        const Nesting nesting(*this, name);
        in_.next();  // '('
        std::vector<Argument> args;
        if (!in_.accept(TokenKind::RightParen)) {
            do {
                const SourceLocation start = in_.peek().where;
                args.push_back({expression(), start});
            } while (in_.accept(TokenKind::Comma));
            if (!in_.accept(TokenKind::RightParen)) in_.fail_expected("',' or ')'");
        }
        if (const std::optional<double> folded = fold_builtin_function(name.text, args)) return *folded;
        return call_builtin_function(in_, name, args);
    }

    /// A named algebraic surface: constant parameters, then optionally the
    /// point (a vector) to evaluate it at — algebraic_surfaces.hpp.
    Value algebraic(const Token& name, const AlgebraicSurface& surface) {
        const Nesting nesting(*this, name);
        in_.next();  // '('
        std::vector<Value> args;
        std::vector<SourceLocation> starts;
        if (!in_.accept(TokenKind::RightParen)) {
            do {
                starts.push_back(in_.peek().where);
                args.push_back(expression());
            } while (in_.accept(TokenKind::Comma));
            if (!in_.accept(TokenKind::RightParen)) in_.fail_expected("',' or ')'");
        }
        const std::string fn(name.text);
        const std::string call_it = "; call it as " + signature(surface);
        std::optional<ExprVector> point;
        if (!args.empty() && args.back().is_vector()) {
            point = args.back().vector();
            args.pop_back();
        }
        for (std::size_t i = 0; i < args.size(); ++i) {
            if (args[i].is_vector())
                in_.fail(starts[i], fn + " takes the point (a vector) only as its last argument, but argument " +
                                        std::to_string(i + 1) + " is a vector" + call_it);
        }
        const std::size_t most = surface.parameters.size();
        if (args.size() > most)
            in_.fail(name.where, fn + " takes at most " + plural(most, "number") + " and a point, but " +
                                     std::to_string(args.size()) + (args.size() == 1 ? " number was" : " numbers were") +
                                     " given" + call_it);
        std::vector<double> values;
        for (std::size_t i = 0; i < args.size(); ++i)
            values.push_back(constant_number(in_, args[i], starts[i],
                                             fn + " parameter " + std::string(surface.parameters[i].name)));
        const std::string problem = surface.check(with_defaults(surface, values));
        if (!problem.empty()) in_.fail(name.where, fn + ": " + problem + call_it);
        return build_algebraic_surface(surface, values, point.value_or(ExprVector{var_x(), var_y(), var_z()}));
    }

    /// model("file.vm"): a fidget .vm model, its path relative to this scene file.
    Value model(const Token& name) {
        in_.next();  // '('
        if (!in_.at(TokenKind::String)) in_.fail_expected("a file name in quotes, as in model(\"bear.vm\"),");
        const Token& file = in_.next();
        in_.expect(TokenKind::RightParen);
        const std::filesystem::path path = resolve_path(context_.base_dir, file.text);
        try {
            return context_.models.load(path, path.string());
        } catch (const FileReadError& e) {
            in_.fail(name.where, "cannot open model '" + path.string() + "': " + e.what());
        }
    }

    /// a op b for the binary operators, on numbers and, where it means something, vectors.
    Value combine(const Token& op, const Value& a, const Value& b) {
        if (a.is_constant() && b.is_constant()) {  // as Expr's constant folding takes it
            const double p = a.constant();
            const double q = b.constant();
            switch (op.kind) {
                case TokenKind::Plus: return apply_op<double>(Op::Add, p, q, 0);
                case TokenKind::Minus: return apply_op<double>(Op::Sub, p, q, 0);
                case TokenKind::Star: return apply_op<double>(Op::Mul, p, q, 0);
                case TokenKind::Slash: return apply_op<double>(Op::Div, p, q, 0);
                default: return pow_constant(p, q);  // '^'
            }
        }
        if (!a.is_vector() && !b.is_vector()) {
            const Expr p = a.number();
            const Expr q = b.number();
            switch (op.kind) {
                case TokenKind::Plus: return p + q;
                case TokenKind::Minus: return p - q;
                case TokenKind::Star: return p * q;
                case TokenKind::Slash: return p / q;
                default: return pow(p, q);  // '^'; an integer constant exponent makes powi
            }
        }
        const auto each = [](const ExprVector& u, auto f) { return ExprVector{f(u[0], 0), f(u[1], 1), f(u[2], 2)}; };
        switch (op.kind) {
            case TokenKind::Plus:
            case TokenKind::Minus:
                if (a.is_vector() && b.is_vector()) {
                    const ExprVector& v = b.vector();
                    const bool plus = op.kind == TokenKind::Plus;
                    return each(a.vector(), [&](const Expr& u, int i) { return plus ? u + v[i] : u - v[i]; });
                }
                break;
            case TokenKind::Star:
                if (a.is_vector() != b.is_vector()) {
                    const Expr& s = a.is_vector() ? b.number() : a.number();
                    return each(a.is_vector() ? a.vector() : b.vector(), [&](const Expr& u, int) { return u * s; });
                }
                break;
            case TokenKind::Slash:
                if (a.is_vector() && !b.is_vector())
                    return each(a.vector(), [&](const Expr& u, int) { return u / b.number(); });
                break;
            default: break;
        }
        const std::string operands = a.is_vector() && b.is_vector()
                                         ? "two vectors"
                                         : std::string(a.kind_name()) + " and " + std::string(b.kind_name());
        in_.fail(op.where, "cannot apply '" + std::string(op.text) + "' to " + operands);
    }

    TokenStream& in_;
    const ExpressionContext& context_;
    int depth_ = 0;
};

}  // namespace

Value parse_expression(TokenStream& in, const ExpressionContext& context) {
    const SourceLocation start = in.peek().where;
    try {
        return ExpressionParser(in, context).expression();
    } catch (const ExpressionTooLarge& e) {
        in.fail(start, std::string("this expression is too large: ") + e.what() + " (docs/limits.md)");
    }
}

std::vector<std::string> function_names() {
    std::vector<std::string> names;
    for (const std::string_view name : builtin_function_names()) names.emplace_back(name);
    for (const AlgebraicSurface& surface : algebraic_surfaces()) names.emplace_back(surface.name);
    names.emplace_back(model_function);
    return names;
}

Value evaluate_expression_text(std::string_view text, const std::vector<std::pair<std::string, Value>>& bindings,
                               const std::string& file_name, const std::filesystem::path& base_dir, double clock) {
    TokenStream in(file_name, std::string(text));
    Scope scope;
    for (const auto& [name, value] : bindings) {
        if (is_builtin_name(name) || scope.find(name))
            throw SceneError(file_name, "'" + name + "' cannot be bound: it is a built-in name or bound twice");
        scope.define(name, {value, file_name, nullptr});
    }
    ModelLibrary models;
    const Value value = parse_expression(in, {scope, models, base_dir, SceneLimits{}.expression_nesting, clock});
    if (!in.at(TokenKind::End)) in.fail_expected("the end of the expression");
    return value;
}

bool is_builtin_name(std::string_view name) {
    return builtin_value(name) || name == clock_name || name == model_function || is_builtin_function(name) ||
           find_algebraic_surface(name) != nullptr;
}

}  // namespace zeroset
