// The .vm reader. Opcodes are looked up in the op table by their .vm names;
// fidget's other opcodes that mean something here are built from ops (see
// fidget's Context::from_text): recip, copy, ceil, round (half away from 0),
// mod (fidget's rem_euclid, in [0, |b|)), asin and acos. The rest (compare,
// and, or, not, mix — a hash, not GLSL's mix — and rand) stay unknown
// opcodes.
#include "zeroset/expr/vm_import.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "zeroset/expr/functions.hpp"

namespace zeroset {

namespace {

struct Token {
    std::string_view text;
    int column;  // 1-based
};

std::vector<Token> split(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i >= line.size() || line[i] == '#') break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return tokens;
}

/// A fidget opcode written with the op table's ops.
struct Composite {
    std::string_view name;
    int arity;
    Expr (*unary)(const Expr&);
    Expr (*binary)(const Expr&, const Expr&);
};

// round(a) = sign(a)·⌊|a| + ½⌋, the sign as a / max(|a|, ¼) (exactly ±1 where
// the rounded magnitude is not 0); asin and acos through atan2 keep their
// domain: √((1 − a)(1 + a)) is NaN for |a| > 1.
constexpr Composite composites[] = {
    {"ceil", 1, [](const Expr& a) { return ceil(a); }, nullptr},
    {"round", 1, [](const Expr& a) { return floor(abs(a) + 0.5) * (a / max(abs(a), Expr(0.25))); },
     nullptr},
    {"asin", 1, [](const Expr& a) { return atan2(a, sqrt((1.0 - a) * (1.0 + a))); }, nullptr},
    {"acos", 1, [](const Expr& a) { return atan2(sqrt((1.0 - a) * (1.0 + a)), a); }, nullptr},
    {"mod", 2, nullptr, [](const Expr& a, const Expr& b) { return mod(a, abs(b)); }},
};

const Composite* composite_opcode(std::string_view name) {
    for (const Composite& c : composites)
        if (c.name == name) return &c;
    return nullptr;
}

/// The next line of the stream, ended by "\n", "\r\n" or a lone "\r"
/// (files from old Macs): false at the end.
bool next_line(std::istream& in, std::string& line) {
    line.clear();
    bool any = false;
    for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
        any = true;
        if (c == '\n') return true;
        if (c == '\r') {
            if (in.peek() == '\n') in.get();
            return true;
        }
        line.push_back(static_cast<char>(c));
    }
    return any;
}

}  // namespace

Expr import_vm(std::istream& in) {
    struct Defined {
        Expr value;
        int line;
    };
    std::unordered_map<std::string, Defined> values;
    std::string line;
    int line_number = 0;
    bool have_output = false;
    Expr output;
    while (next_line(in, line)) {
        ++line_number;
        const std::vector<Token> tokens = split(line);
        if (tokens.empty()) continue;
        const auto fail = [&](const Token& at, const std::string& message) -> VmImportError {
            return {line_number, at.column, message};
        };
        if (tokens.size() < 2) throw fail(tokens[0], "expected `name opcode args…`");
        const std::string name(tokens[0].text);
        const std::string_view opcode = tokens[1].text;

        const auto operand = [&](std::size_t k) -> Expr {
            if (k >= tokens.size()) throw fail(tokens[1], "`" + std::string(opcode) + "` is missing an operand");
            const auto it = values.find(std::string(tokens[k].text));
            if (it == values.end()) throw fail(tokens[k], "unknown value `" + std::string(tokens[k].text) + "`");
            return it->second.value;
        };
        const auto expect_count = [&](std::size_t count) {
            if (tokens.size() != count + 2)
                throw fail(tokens[1], "`" + std::string(opcode) + "` takes " + std::to_string(count) + " operand(s), got " +
                                          std::to_string(tokens.size() - 2));
        };

        Expr value;
        if (opcode == "const") {
            expect_count(1);
            double c = 0.0;
            const std::string_view text = tokens[2].text;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), c);
            if (error != std::errc() || end != text.data() + text.size())
                throw fail(tokens[2], "invalid number `" + std::string(text) + "`");
            if (!std::isfinite(c)) throw fail(tokens[2], "a constant must be finite, not `" + std::string(text) + "`");
            value = Expr(c);
        } else if (opcode == "var-x" || opcode == "var-y" || opcode == "var-z") {
            expect_count(0);
            value = opcode == "var-x" ? var_x() : opcode == "var-y" ? var_y() : var_z();
        } else if (opcode == "recip") {
            expect_count(1);
            value = Expr(1.0) / operand(2);
        } else if (opcode == "copy") {
            expect_count(1);
            value = operand(2);
        } else if (const auto composite = composite_opcode(opcode)) {
            expect_count(static_cast<std::size_t>(composite->arity));
            const Expr a = operand(2);
            value = composite->arity == 1 ? composite->unary(a) : composite->binary(a, operand(3));
        } else if (const auto op = op_from_name(opcode); op && op != Op::Powi && op != Op::Const) {
            const int arity = op_arity(*op);
            expect_count(static_cast<std::size_t>(arity));
            const Expr a = operand(2);  // before operand(3): the first unknown operand is the one reported
            value = arity == 1 ? Expr::make(*op, a) : Expr::make(*op, a, operand(3));
        } else {
            throw fail(tokens[1], "unknown opcode `" + std::string(opcode) + "`");
        }
        if (const auto earlier = values.find(name); earlier != values.end())
            throw fail(tokens[0], "`" + name + "` is already defined (line " + std::to_string(earlier->second.line) +
                                      "); a name is defined once");
        values.emplace(name, Defined{value, line_number});
        output = value;
        have_output = true;
    }
    if (!have_output) throw VmImportError(line_number, 1, "the model has no clauses");
    return output;
}

}  // namespace zeroset
