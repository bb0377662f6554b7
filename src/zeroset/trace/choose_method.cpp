// The rule behind `method auto`. A polynomial surface (degree ≤ 32) gets the
// polynomial method: exact coefficients of F(t) and a root solver. Any other
// surface is sphere traced. Sphere tracing is as guaranteed as the interval
// method (its ε-segments are isolated by intervals, sphere_tracer.hpp) and
// includes its test — a segment whose enclosure of f excludes 0 is skipped
// whole — while stepping by cheap point values where the interval method
// bisects with costly Jet<Interval> enclosures. Measured in docs/methods.md
// (`auto`): 1.1–3.9× faster on every non-polynomial scene of scenes/ at
// 640×480, and faster on bear.vm, with the same pixels.
#include "zeroset/trace/choose_method.hpp"

#include "zeroset/expr/ray_polynomial.hpp"

namespace zeroset {

Method resolve_method(Method requested, const Tape& tape) {
    if (requested != Method::Auto) return requested;
    const int degree = polynomial_degree(tape);
    if (degree >= 1 && degree <= Polynomial::max_degree) return Method::Polynomial;  // exact F(t), survey §3.4
    return Method::Sphere;
}

}  // namespace zeroset
