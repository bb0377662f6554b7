// Hash-consing, constant folding and printing for Expr.
#include "zeroset/expr/expr.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "zeroset/math/scalar.hpp"

namespace zeroset {

namespace {

struct Key {
    Op op;
    int exponent;
    std::uint64_t value_bits;
    const void* a;
    const void* b;
    bool operator==(const Key&) const = default;
};

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::size_t h = std::hash<std::uint64_t>{}(k.value_bits);
        const auto mix = [&h](std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
        mix(static_cast<std::size_t>(k.op));
        mix(static_cast<std::size_t>(k.exponent));
        mix(std::hash<const void*>{}(k.a));
        mix(std::hash<const void*>{}(k.b));
        return h;
    }
};

/// The table of live nodes. Entries are weak, so unused expressions are freed;
/// dead entries are swept whenever the table has doubled since the last sweep.
struct InternTable {
    std::mutex mutex;
    std::unordered_map<Key, std::weak_ptr<const ExprNode>, KeyHash> nodes;
    std::size_t sweep_at = 1024;
};

InternTable& table() {
    static auto* t = new InternTable;  // never destroyed: Exprs may outlive static destruction
    return *t;
}

/// The structural hash of a node from its parts and its operands' hashes.
std::uint64_t shape_of(Op op, int exponent, std::uint64_t value_bits, const ExprNode* a, const ExprNode* b) {
    std::uint64_t h = 0x243f6a8885a308d3ULL;
    const auto mix = [&h](std::uint64_t v) {
        h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdULL;
        h ^= h >> 33;
    };
    mix(static_cast<std::uint64_t>(op));
    mix(static_cast<std::uint64_t>(static_cast<std::uint32_t>(exponent)));
    mix(value_bits);
    mix(a ? a->shape : 0);
    mix(b ? b->shape : 0);
    return h;
}

/// A total order on structures that depends on them alone: by shape, and
/// on the (unseen in practice) collision of two shapes, by their parts.
bool structurally_before(const ExprNode* a, const ExprNode* b) {
    if (a == b || !b) return false;
    if (!a) return true;
    if (a->shape != b->shape) return a->shape < b->shape;
    if (a->op != b->op) return a->op < b->op;
    if (a->exponent != b->exponent) return a->exponent < b->exponent;
    const auto va = std::bit_cast<std::uint64_t>(a->value), vb = std::bit_cast<std::uint64_t>(b->value);
    if (va != vb) return va < vb;
    if (a->a != b->a) return structurally_before(a->a.get(), b->a.get());
    return structurally_before(a->b.get(), b->b.get());
}

std::atomic<std::size_t> live_nodes{0};
std::atomic<std::uint64_t> nodes_made{0};
std::atomic<std::size_t> node_limit{4'000'000};

}  // namespace

Expr Expr::intern(Op op, double value, int n, const Expr* a, const Expr* b) {
    const Key key{op, n, std::bit_cast<std::uint64_t>(value), a ? a->id() : nullptr, b ? b->id() : nullptr};
    InternTable& t = table();
    std::lock_guard lock(t.mutex);
    if (auto it = t.nodes.find(key); it != t.nodes.end()) {
        if (auto live = it->second.lock()) return Expr(std::move(live));
    }
    if (live_nodes.load(std::memory_order_relaxed) >= node_limit.load(std::memory_order_relaxed))
        throw ExpressionTooLarge("the expressions have more than " + std::to_string(node_limit.load()) +
                                 " distinct operations in all");
    const bool is_var = op == Op::VarX || op == Op::VarY || op == Op::VarZ;
    const bool constant_valued =
        !is_var && (!a || a->is_constant_valued()) && (!b || b->is_constant_valued());
    // Built in place (no temporary, whose destructor would count as a node freed).
    const std::uint64_t shape = shape_of(op, n, key.value_bits, a ? a->node_.get() : nullptr, b ? b->node_.get() : nullptr);
    auto node = std::make_shared<const ExprNode>(op, n, value, constant_valued, shape, nodes_made++, a ? a->node_ : nullptr,
                                                 b ? b->node_ : nullptr);
    t.nodes[key] = node;
    live_nodes.fetch_add(1, std::memory_order_relaxed);
    if (t.nodes.size() >= t.sweep_at) {
        std::erase_if(t.nodes, [](const auto& entry) { return entry.second.expired(); });
        t.sweep_at = std::max<std::size_t>(1024, 2 * t.nodes.size());
    }
    return Expr(std::move(node));
}

std::size_t max_expression_nodes() { return node_limit.load(); }
std::size_t set_max_expression_nodes(std::size_t limit) { return node_limit.exchange(limit); }
std::size_t live_expression_nodes() { return live_nodes.load(); }

ExprNode::~ExprNode() {
    live_nodes.fetch_sub(1, std::memory_order_relaxed);
    // Operands whose last owner is this node are queued instead of destroyed
    // here; the outermost destructor on the thread drains the queue. The
    // queue is reached through a plain pointer, never destroyed, so nodes
    // held by static objects can still be released at program exit, after
    // the thread's thread_local objects are gone.
    using Queue = std::vector<std::shared_ptr<const ExprNode>>;
    thread_local Queue* const pending = new Queue;
    thread_local bool draining = false;
    if (a) pending->push_back(std::move(a));
    if (b) pending->push_back(std::move(b));
    if (draining) return;
    draining = true;
    while (!pending->empty()) {
        std::shared_ptr<const ExprNode> next = std::move(pending->back());
        pending->pop_back();
        next.reset();  // may run ~ExprNode, which only queues
    }
    draining = false;
}

Expr::Expr() : Expr(0.0) {}
Expr::Expr(double constant) : node_(intern(Op::Const, constant, 0, nullptr, nullptr).node_) {}

Op Expr::op() const { return node_->op; }
std::uint64_t Expr::creation_order() const { return node_->serial; }
double Expr::value() const { return node_->value; }
int Expr::exponent() const { return node_->exponent; }
Expr Expr::operand(int i) const { return Expr(i == 0 ? node_->a : node_->b); }
bool Expr::is_constant_valued() const { return node_->constant_valued; }

Expr var_x() { return Expr::intern(Op::VarX, 0.0, 0, nullptr, nullptr); }
Expr var_y() { return Expr::intern(Op::VarY, 0.0, 0, nullptr, nullptr); }
Expr var_z() { return Expr::intern(Op::VarZ, 0.0, 0, nullptr, nullptr); }

namespace {

/// How a sum's terms become the operands of a two-argument op that
/// replaces f(Σ terms): Square → its operand (for hypot), Exp → its
/// exponent and a positive constant c → ln c (for log-sum-exp).
enum class SumPattern { SquareTerms, ExpTerms };

std::optional<Expr> term_operand(const Expr& term, SumPattern pattern) {
    if (pattern == SumPattern::SquareTerms) {
        if (term.op() == Op::Square) return term.operand(0);
    } else {
        if (term.op() == Op::Exp) return term.operand(0);
        if (term.is_constant() && term.value() > 0.0) return Expr(std::log(term.value()));
    }
    return std::nullopt;
}

/// True when `sum` is an Add tree of at most `max_terms` terms that all
/// match the pattern (checked without recursion: a long chain of adds that
/// does not match costs at most max_terms steps).
bool matches(const Expr& sum, SumPattern pattern) {
    constexpr std::size_t max_terms = 64;
    if (sum.op() != Op::Add) return false;
    std::vector<Expr> pending{sum};
    std::size_t terms = 0;
    while (!pending.empty()) {
        const Expr e = pending.back();
        pending.pop_back();
        if (++terms > 2 * max_terms) return false;  // adds and terms counted together
        if (e.op() == Op::Add) {
            pending.push_back(e.operand(0));
            pending.push_back(e.operand(1));
        } else if (!term_operand(e, pattern)) {
            return false;
        }
    }
    return true;
}

/// The op over the sum's tree, add for add: the nesting follows the sum as
/// it was built, so the same sum always gives the same expression.
Expr fold_sum(const Expr& sum, SumPattern pattern, Op op) {
    if (sum.op() != Op::Add) return *term_operand(sum, pattern);
    return Expr::make(op, fold_sum(sum.operand(0), pattern, op), fold_sum(sum.operand(1), pattern, op));
}

}  // namespace

Expr Expr::make(Op op, const Expr& a, const Expr& b, int n) {
    const int arity = op_arity(op);
    // Two patterns of written-out models become ops with tighter enclosures:
    // ln(Σ eᵘⁱ) is nested log-sum-exps of the uᵢ (no overflow; its interval
    // runs corner to corner), √(Σ uᵢ²) nested hypots (the same values to an
    // ulp, and slopes uᵢ/h within [−1, 1] where sqrt's 1/(2√s) is unbounded:
    // a norm over a box around its centre keeps L = 1).
    if (op == Op::Log && matches(a, SumPattern::ExpTerms)) return fold_sum(a, SumPattern::ExpTerms, Op::LogSumExp);
    if (op == Op::Sqrt && matches(a, SumPattern::SquareTerms)) return fold_sum(a, SumPattern::SquareTerms, Op::Hypot);
    // Constant folding: an op over constants is the constant it evaluates to.
    if (arity >= 1 && a.is_constant() && (arity < 2 || b.is_constant())) {
        return Expr(apply_op<double>(op, a.value(), arity == 2 ? b.value() : 0.0, n));
    }
    // Operand order does not matter for these: keep one canonical order so
    // that a + b and b + a share a node — by structure, not by address, so
    // that it is the same in every process.
    const bool commutative = op == Op::Add || op == Op::Mul || op == Op::Min || op == Op::Max || op == Op::Hypot ||
                             op == Op::LogSumExp;
    if (commutative && structurally_before(b.node_.get(), a.node_.get())) return intern(op, 0.0, n, &b, &a);
    return intern(op, 0.0, n, &a, arity == 2 ? &b : nullptr);
}

std::size_t Expr::node_count() const {
    std::unordered_set<const void*> seen;
    std::vector<const ExprNode*> stack{node_.get()};
    while (!stack.empty()) {
        const ExprNode* n = stack.back();
        stack.pop_back();
        if (!n || !seen.insert(n).second) continue;
        stack.push_back(n->a.get());
        stack.push_back(n->b.get());
    }
    return seen.size();
}

std::vector<Expr> operands_first(const Expr& root, const std::function<bool(const Expr&)>& closed) {
    std::vector<Expr> order;
    std::unordered_map<const void*, bool> visited;  // false: on the stack, true: listed
    std::vector<std::pair<Expr, bool>> stack{{root, false}};  // (node, operands listed)
    while (!stack.empty()) {
        auto [e, expanded] = stack.back();
        stack.pop_back();
        if (expanded) {
            if (!visited[e.id()]) {
                visited[e.id()] = true;
                order.push_back(e);
            }
            continue;
        }
        if (visited.contains(e.id())) continue;
        visited[e.id()] = false;
        stack.emplace_back(e, true);
        const int arity = closed && closed(e) ? 0 : op_arity(e.op());
        const bool swap = arity == 2 && e.operand(1).creation_order() < e.operand(0).creation_order();
        for (int i = arity - 1; i >= 0; --i) {
            const Expr child = e.operand(swap ? 1 - i : i);
            if (!visited.contains(child.id())) stack.emplace_back(child, false);
        }
    }
    return order;
}

namespace {

/// One step of writing an expression out: a node to write, a piece of
/// text, or a Powi node's exponent (written after its base).
struct TextStep {
    enum class Kind { Node, Text, Exponent } kind;
    Expr node;
    std::string_view text;
};

}  // namespace

std::string number_text(double v) {
    // The scene language has no literal for ∞ or NaN: expressions that fold to them.
    if (v != v) return "(0 * (1e308 * 10))";
    if (std::isinf(v)) return v > 0.0 ? "(1e308 * 10)" : "(-1e308 * 10)";
    std::array<char, 32> buffer{};
    const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v, std::chars_format::general, 17);
    return {buffer.data(), written.ptr};
}

bool append_infix(std::string& out, const Expr& e, const NameOf& name_of, std::size_t max_chars) {
    std::vector<TextStep> steps{{TextStep::Kind::Node, e, {}}};
    // The steps after a node's first piece, pushed last first.
    const auto then = [&steps](std::initializer_list<TextStep> rest) {
        steps.insert(steps.end(), std::rbegin(rest), std::rend(rest));
    };
    const auto node = [](const Expr& n) { return TextStep{TextStep::Kind::Node, n, {}}; };
    const auto text = [](std::string_view t) { return TextStep{TextStep::Kind::Text, Expr(), t}; };
    while (!steps.empty() && out.size() <= max_chars) {
        const TextStep step = std::move(steps.back());
        steps.pop_back();
        if (step.kind == TextStep::Kind::Text) {
            out += step.text;
            continue;
        }
        const Expr& n = step.node;
        if (step.kind == TextStep::Kind::Exponent) {
            out += '^';
            out += std::to_string(n.exponent());
            continue;
        }
        if (name_of) {
            if (const std::string* name = name_of(n)) {
                out += *name;
                continue;
            }
        }
        const auto infix = [&](std::string_view op) {
            out += '(';
            then({node(n.operand(0)), text(op), node(n.operand(1)), text(")")});
        };
        switch (n.op()) {
            case Op::Const: out += number_text(n.value()); break;
            case Op::VarX: out += 'x'; break;
            case Op::VarY: out += 'y'; break;
            case Op::VarZ: out += 'z'; break;
            case Op::Add: infix(" + "); break;
            case Op::Sub: infix(" - "); break;
            case Op::Mul: infix(" * "); break;
            case Op::Div: infix(" / "); break;
            case Op::Neg:
                out += '-';
                then({node(n.operand(0))});
                break;
            case Op::Powi: {
                // (−x)^2, not −x^2, which reads as −(x^2); likewise a power of a power.
                const Expr base = n.operand(0);
                const bool wrap =
                    base.op() == Op::Neg || base.op() == Op::Powi || (base.is_constant() && base.value() < 0.0);
                if (wrap) out += '(';
                then({node(base), text(wrap ? ")" : ""), TextStep{TextStep::Kind::Exponent, n, {}}});
                break;
            }
            default:
                // The scene language's function is the op's .vm name with
                // '_' for '-' (log-sum-exp is log_sum_exp).
                for (const char c : op_name(n.op())) out += c == '-' ? '_' : c;
                out += '(';
                if (op_arity(n.op()) == 2) then({node(n.operand(0)), text(", "), node(n.operand(1)), text(")")});
                else then({node(n.operand(0)), text(")")});
        }
    }
    if (out.size() <= max_chars) return true;
    out.resize(max_chars);
    return false;
}

std::string Expr::to_string(std::size_t max_chars) const {
    std::string out;
    if (!append_infix(out, *this, {}, max_chars)) out += "…";
    return out;
}

std::optional<Op> op_from_name(std::string_view name) {
    for (int i = 0; i < op_count; ++i) {
        const auto op = static_cast<Op>(i);
        if (op_name(op) == name) return op;
    }
    return std::nullopt;
}

Expr operator+(const Expr& a, const Expr& b) {
    if (a.is_constant() && a.value() == 0.0) return b;
    if (b.is_constant() && b.value() == 0.0) return a;
    return Expr::make(Op::Add, a, b);
}
Expr operator-(const Expr& a, const Expr& b) {
    if (b.is_constant() && b.value() == 0.0) return a;
    return Expr::make(Op::Sub, a, b);
}
Expr operator*(const Expr& a, const Expr& b) {
    if (a.is_constant() && a.value() == 1.0) return b;
    if (b.is_constant() && b.value() == 1.0) return a;
    return Expr::make(Op::Mul, a, b);
}
Expr operator/(const Expr& a, const Expr& b) {
    if (b.is_constant() && b.value() == 1.0) return a;
    return Expr::make(Op::Div, a, b);
}
Expr operator-(const Expr& a) {
    if (a.op() == Op::Neg) return a.operand(0);
    return Expr::make(Op::Neg, a);
}
Expr square(const Expr& a) { return Expr::make(Op::Square, a); }
Expr sqrt(const Expr& a) { return Expr::make(Op::Sqrt, a); }
Expr abs(const Expr& a) { return Expr::make(Op::Abs, a); }
Expr exp(const Expr& a) { return Expr::make(Op::Exp, a); }
Expr log(const Expr& a) { return Expr::make(Op::Log, a); }
Expr sin(const Expr& a) { return Expr::make(Op::Sin, a); }
Expr cos(const Expr& a) { return Expr::make(Op::Cos, a); }
Expr tan(const Expr& a) { return Expr::make(Op::Tan, a); }
Expr atan(const Expr& a) { return Expr::make(Op::Atan, a); }
Expr atan2(const Expr& y, const Expr& x) { return Expr::make(Op::Atan2, y, x); }
Expr floor(const Expr& a) { return Expr::make(Op::Floor, a); }
Expr hypot(const Expr& a, const Expr& b) { return Expr::make(Op::Hypot, a, b); }
Expr log_sum_exp(const Expr& a, const Expr& b) { return Expr::make(Op::LogSumExp, a, b); }
Expr powi(const Expr& a, int n) {
    if (n == 0) return Expr(1.0);
    if (n == 1) return a;
    if (n == 2) return square(a);
    return Expr::make(Op::Powi, a, Expr(), n);
}
namespace {

/// The exponent n when a^b is built as powi(a, n): b integral, |b| ≤ 1024.
std::optional<int> powi_exponent(double b) {
    if (b == std::round(b) && std::abs(b) <= 1024.0) return static_cast<int>(b);
    return std::nullopt;
}

}  // namespace

Expr pow(const Expr& a, const Expr& b) {
    if (b.is_constant()) {
        if (const std::optional<int> n = powi_exponent(b.value())) return powi(a, *n);
    }
    return Expr::make(Op::Pow, a, b);
}
double pow_constant(double a, double b) {
    const std::optional<int> n = powi_exponent(b);
    return n ? apply_op<double>(Op::Powi, a, 0.0, *n) : apply_op<double>(Op::Pow, a, b, 0);
}
Expr min(const Expr& a, const Expr& b) { return a == b ? a : Expr::make(Op::Min, a, b); }
Expr max(const Expr& a, const Expr& b) { return a == b ? a : Expr::make(Op::Max, a, b); }

}  // namespace zeroset
