// Recognising a sum of Gaussians: the expression's terms by a walk over its
// sums, each exponent as a quadratic in x, y, z.
#include "zeroset/expr/gaussian_sum.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace zeroset {

namespace {

/// A polynomial of degree ≤ 2 in x, y, z: the coefficients of
/// 1, x, y, z, x², y², z², xy, xz, yz.
struct Quadratic {
    std::array<double, 10> c{};

    [[nodiscard]] bool is_constant() const {
        for (std::size_t i = 1; i < c.size(); ++i)
            if (c[i] != 0.0) return false;
        return true;
    }
    [[nodiscard]] bool is_linear() const {
        for (std::size_t i = 4; i < c.size(); ++i)
            if (c[i] != 0.0) return false;
        return true;
    }
};

Quadratic scaled(Quadratic q, double s) {
    for (double& v : q.c) v *= s;
    return q;
}

Quadratic sum(Quadratic a, const Quadratic& b, double sign) {
    for (std::size_t i = 0; i < a.c.size(); ++i) a.c[i] += sign * b.c[i];
    return a;
}

std::optional<Quadratic> product(const Quadratic& a, const Quadratic& b) {
    if (a.is_constant()) return scaled(b, a.c[0]);
    if (b.is_constant()) return scaled(a, b.c[0]);
    if (!a.is_linear() || !b.is_linear()) return std::nullopt;  // degree 3 or more
    Quadratic p;
    p.c[0] = a.c[0] * b.c[0];
    for (std::size_t i = 1; i <= 3; ++i) p.c[i] = a.c[0] * b.c[i] + b.c[0] * a.c[i];
    for (std::size_t i = 1; i <= 3; ++i) p.c[i + 3] = a.c[i] * b.c[i];
    p.c[7] = a.c[1] * b.c[2] + a.c[2] * b.c[1];
    p.c[8] = a.c[1] * b.c[3] + a.c[3] * b.c[1];
    p.c[9] = a.c[2] * b.c[3] + a.c[3] * b.c[2];
    return p;
}

/// e as a quadratic in x, y, z, or nothing (another op, degree above 2, or
/// nested deeper than an exponent of a real model is).
std::optional<Quadratic> quadratic_of(const Expr& e, int depth = 0) {
    if (depth > 64) return std::nullopt;
    Quadratic q;
    switch (e.op()) {
        case Op::Const: q.c[0] = e.value(); return q;
        case Op::VarX: q.c[1] = 1.0; return q;
        case Op::VarY: q.c[2] = 1.0; return q;
        case Op::VarZ: q.c[3] = 1.0; return q;
        case Op::Neg: {
            const auto a = quadratic_of(e.operand(0), depth + 1);
            return a ? std::optional(scaled(*a, -1.0)) : std::nullopt;
        }
        case Op::Add:
        case Op::Sub:
        case Op::Mul: {
            const auto a = quadratic_of(e.operand(0), depth + 1);
            const auto b = a ? quadratic_of(e.operand(1), depth + 1) : std::nullopt;
            if (!b) return std::nullopt;
            if (e.op() == Op::Mul) return product(*a, *b);
            return sum(*a, *b, e.op() == Op::Add ? 1.0 : -1.0);
        }
        case Op::Div: {
            if (!e.operand(1).is_constant() || e.operand(1).value() == 0.0) return std::nullopt;
            const auto a = quadratic_of(e.operand(0), depth + 1);
            return a ? std::optional(scaled(*a, 1.0 / e.operand(1).value())) : std::nullopt;
        }
        case Op::Square: {
            const auto a = quadratic_of(e.operand(0), depth + 1);
            return a ? product(*a, *a) : std::nullopt;
        }
        case Op::Powi: {
            const auto a = e.exponent() >= 0 && e.exponent() <= 2 ? quadratic_of(e.operand(0), depth + 1) : std::nullopt;
            if (!a) return std::nullopt;
            if (e.exponent() == 0) return Quadratic{{1.0}};
            return e.exponent() == 1 ? a : product(*a, *a);
        }
        default: return std::nullopt;
    }
}

/// scale·exp(exponent): one Gaussian term of the sum.
struct Term {
    double scale;
    Expr exponent;
};

/// f as constant + Σ scaleᵢ·exp(exponentᵢ) through its sums, differences,
/// negations and products by constants; nothing when another op is met.
std::optional<std::pair<double, std::vector<Term>>> terms_of(const Expr& f) {
    double constant = 0.0;
    std::vector<Term> terms;
    std::vector<std::pair<Expr, double>> pending{{f, 1.0}};
    // A DAG walked as a tree may fan out: stop well before that could matter.
    const std::size_t budget = 4 * f.node_count() + 16;
    for (std::size_t visited = 0; !pending.empty(); ++visited) {
        if (visited == budget) return std::nullopt;
        const auto [e, scale] = pending.back();
        pending.pop_back();
        switch (e.op()) {
            case Op::Const: constant += scale * e.value(); break;
            case Op::Exp: terms.push_back({scale, e.operand(0)}); break;
            case Op::Neg: pending.emplace_back(e.operand(0), -scale); break;
            case Op::Add:
            case Op::Sub:
                pending.emplace_back(e.operand(0), scale);
                pending.emplace_back(e.operand(1), e.op() == Op::Add ? scale : -scale);
                break;
            case Op::Mul:
                if (e.operand(0).is_constant()) pending.emplace_back(e.operand(1), scale * e.operand(0).value());
                else if (e.operand(1).is_constant()) pending.emplace_back(e.operand(0), scale * e.operand(1).value());
                else return std::nullopt;
                break;
            default: return std::nullopt;
        }
    }
    if (terms.empty()) return std::nullopt;
    return std::pair{constant, std::move(terms)};
}

/// scale·exp(−k·|p − c|² + b) as a component of f = T − Σ s·e^(B(u − 1)):
/// R = 1/√k and B = −1, so s·K = s·e·e^(−k|p − c|²) and s = −scale·e^(b − 1).
std::optional<BlobComponent> component_of(const Term& term) {
    const auto q = quadratic_of(term.exponent);
    if (!q) return std::nullopt;
    const auto& c = q->c;
    const double k = -c[4];
    if (!(k > 0.0) || c[5] != c[4] || c[6] != c[4] || c[7] != 0.0 || c[8] != 0.0 || c[9] != 0.0) return std::nullopt;
    BlobComponent component;
    component.center = {c[1] / (2.0 * k), c[2] / (2.0 * k), c[3] / (2.0 * k)};
    const double b = c[0] + k * dot(component.center, component.center);
    component.radius = 1.0 / std::sqrt(k);
    component.blobbiness = -1.0;
    component.strength = -term.scale * std::exp(b - 1.0);
    return component;
}

}  // namespace

std::optional<BlobModel> gaussian_sum_as_blob(const Expr& f) {
    const auto split = terms_of(f);
    if (!split) return std::nullopt;
    std::vector<BlobComponent> components;
    components.reserve(split->second.size());
    for (const Term& term : split->second) {
        auto component = component_of(term);
        if (!component) return std::nullopt;
        components.push_back(*component);
    }
    try {
        return BlobModel(BlobKernel::Blinn, split->first, std::move(components));
    } catch (const std::invalid_argument&) {  // T ≤ 0, a strength that under- or overflows, …
        return std::nullopt;
    }
}

}  // namespace zeroset
