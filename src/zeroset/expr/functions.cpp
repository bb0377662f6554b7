// The composite functions, written once as expressions.
#include "zeroset/expr/functions.hpp"

#include <stdexcept>

#include "zeroset/expr/parameter_checks.hpp"

namespace zeroset {

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
