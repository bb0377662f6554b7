// The composite functions, written once as expressions.
#include "zeroset/expr/functions.hpp"

#include <stdexcept>

#include "zeroset/expr/parameter_checks.hpp"

namespace zeroset {

Expr mod(const Expr& a, const Expr& b) { return a - b * floor(a / b); }

Expr clamp(const Expr& a, const Expr& lo, const Expr& hi) { return min(max(a, lo), hi); }

Expr mix(const Expr& a, const Expr& b, const Expr& t) { return a + (b - a) * t; }

Expr smoothstep(const Expr& e0, const Expr& e1, const Expr& a) {
    const Expr s = clamp((a - e0) / (e1 - e0), 0.0, 1.0);
    return square(s) * (3.0 - 2.0 * s);
}

Expr smooth_union(const Expr& a, const Expr& b, double k) {
    if (!(k > 0.0)) throw std::invalid_argument("the blend radius k must be positive");
    return min(a, b) - square(max(k - abs(a - b), 0.0)) / (4.0 * k);
}

Expr smooth_intersection(const Expr& a, const Expr& b, double k) { return -smooth_union(-a, -b, k); }

Expr smooth_difference(const Expr& a, const Expr& b, double k) { return smooth_intersection(a, -b, k); }

Expr algebraic_blend(const Expr& g, const Expr& h, double a, double b) {
    parameter_checks::require_positive(a, "the offset a of g");
    parameter_checks::require_positive(b, "the offset b of h");
    return (4.0 / (a * b)) * g * h - square((1.0 / a) * g + (1.0 / b) * h - 1.0);
}

}  // namespace zeroset
