// Expr: an implicit function f(x, y, z) as a hash-consed expression DAG.
// Building the same subexpression twice returns the same node, so shared
// structure is found for free and a tape evaluates it once. Nodes are
// immutable and shared; an Expr is a cheap handle.
//
//   Expr f = sqrt(square(X) + square(Y) + square(Z)) - 1.0;
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/expr/op.hpp"

namespace zeroset {

struct ExprNode;

class Expr {
public:
    Expr();  // the constant 0
    Expr(double constant);  // NOLINT: implicit, so `x * 2` reads naturally

    [[nodiscard]] Op op() const;
    /// The value of a Const node.
    [[nodiscard]] double value() const;
    /// The integer exponent of a Powi node.
    [[nodiscard]] int exponent() const;
    /// Operand i (0 or 1); only valid below op_arity(op()).
    [[nodiscard]] Expr operand(int i) const;
    [[nodiscard]] bool is_constant() const { return op() == Op::Const; }
    /// True when no x, y or z occurs in the expression.
    [[nodiscard]] bool is_constant_valued() const;

    /// When the node was made, relative to the others (ExprNode::serial).
    [[nodiscard]] std::uint64_t creation_order() const;
    /// Identity of the shared node (equal ids ⇔ structurally equal expressions).
    [[nodiscard]] const void* id() const { return node_.get(); }
    friend bool operator==(const Expr& a, const Expr& b) { return a.node_ == b.node_; }

    /// Number of distinct nodes in the DAG.
    [[nodiscard]] std::size_t node_count() const;
    /// Infix text in the scene language's syntax. A DAG is written as the
    /// tree it unfolds to, which can be far larger (exponentially, where
    /// parts are shared): past `max_chars` the text stops, ending in "…".
    [[nodiscard]] std::string to_string(std::size_t max_chars = std::string::npos) const;

    /// The node for `op` over the given operands (constant-folded and hash-consed).
    static Expr make(Op op, const Expr& a, const Expr& b, int n = 0);
    static Expr make(Op op, const Expr& a) { return make(op, a, Expr(), 0); }

private:
    explicit Expr(std::shared_ptr<const ExprNode> node) : node_(std::move(node)) {}
    static Expr intern(Op op, double value, int n, const Expr* a, const Expr* b);
    friend Expr var_x();
    friend Expr var_y();
    friend Expr var_z();

    std::shared_ptr<const ExprNode> node_;
};

struct ExprNode {
    ExprNode(Op op_, int exponent_, double value_, bool constant_valued_, std::uint64_t shape_, std::uint64_t serial_,
             std::shared_ptr<const ExprNode> a_, std::shared_ptr<const ExprNode> b_)
        : op(op_), exponent(exponent_), value(value_), constant_valued(constant_valued_), shape(shape_),
          serial(serial_), a(std::move(a_)), b(std::move(b_)) {}

    Op op;
    int exponent;  // Powi only
    double value;  // Const only
    bool constant_valued;
    /// A hash of the structure alone (never of addresses): the same in every
    /// process, so that the canonical order of commutative operands — and
    /// with it every rounding — is too (a distributed render's ranks must
    /// compute the same pixels).
    std::uint64_t shape;
    /// The order nodes were made in, process-wide: a model's own order,
    /// which the tape keeps for its schedule (tape.cpp). Unlike `shape` it
    /// may differ between processes, so nothing numeric depends on it.
    std::uint64_t serial;
    std::shared_ptr<const ExprNode> a, b;  // operands (null past the arity)

    /// Releases operands iteratively: a chain of 100 000 nodes must not
    /// recurse 100 000 destructors deep.
    ~ExprNode();
};

/// Building a node past the limit on live expression nodes (below): the
/// expressions would take more memory than any real model needs, so the
/// caller reports the input that asked for them instead.
class ExpressionTooLarge : public std::length_error {
public:
    using std::length_error::length_error;
};

/// The most expression nodes alive at once, process-wide: 4 000 000 by
/// default (about 1 GiB with their tapes); real models have thousands.
std::size_t max_expression_nodes();
/// Sets the limit (tests and the fuzz targets lower it); returns the old one.
std::size_t set_max_expression_nodes(std::size_t limit);
/// The expression nodes alive now.
std::size_t live_expression_nodes();

/// The DAG's nodes from `root` down, each once, operands before their
/// users; of two operands, the one made first is walked first. A node that
/// `closed` says yes to is listed without its operands. Iterative.
std::vector<Expr> operands_first(const Expr& root, const std::function<bool(const Expr&)>& closed = {});

/// A number as the scene language's text writes it: 17 significant digits
/// (read back, the same double), whatever the locale; ∞ and NaN as
/// constant expressions that fold to them.
std::string number_text(double v);

/// A name to write instead of a node's text (a let's, in the scene
/// writer), or null to write the node out.
using NameOf = std::function<const std::string*(const Expr&)>;
/// Appends e's infix text (Expr::to_string) to `out`, with the nodes that
/// `name_of` names written as their names. Stops when `out` — what it held
/// before included — grows past `max_chars`: cut there, and false.
/// Iterative: however deep the expression, it costs heap, not stack.
bool append_infix(std::string& out, const Expr& e, const NameOf& name_of, std::size_t max_chars);

/// The coordinate variables.
Expr var_x();
Expr var_y();
Expr var_z();

Expr operator+(const Expr& a, const Expr& b);
Expr operator-(const Expr& a, const Expr& b);
Expr operator*(const Expr& a, const Expr& b);
Expr operator/(const Expr& a, const Expr& b);
Expr operator-(const Expr& a);
Expr square(const Expr& a);
Expr sqrt(const Expr& a);
Expr abs(const Expr& a);
Expr exp(const Expr& a);
Expr log(const Expr& a);
Expr sin(const Expr& a);
Expr cos(const Expr& a);
Expr tan(const Expr& a);
Expr atan(const Expr& a);
/// The angle of the point (x, y) in (−π, π], as C's atan2(y, x).
Expr atan2(const Expr& y, const Expr& x);
Expr floor(const Expr& a);
/// √(a² + b²), whose derivatives stay bounded where both are 0.
Expr hypot(const Expr& a, const Expr& b);
/// ln(eᵃ + eᵇ) as one op, the smooth maximum of soft blends. log() of a sum
/// whose terms are all exps (or positive constants) builds it by itself, so
/// models written out as ln(exp(a) + exp(b)) get its tight enclosures and
/// lose the overflow of eᵃ.
Expr log_sum_exp(const Expr& a, const Expr& b);
/// a^n for an integer n (square for n = 2).
Expr powi(const Expr& a, int n);
/// a^b; an integral constant b becomes powi.
Expr pow(const Expr& a, const Expr& b);
/// a^b over constants, as pow(Expr(a), Expr(b)) folds it: powi for an integral b.
double pow_constant(double a, double b);
Expr min(const Expr& a, const Expr& b);
Expr max(const Expr& a, const Expr& b);

}  // namespace zeroset
