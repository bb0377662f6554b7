// The rule behind `method auto`. A polynomial surface (degree ≤ 32) gets the
// polynomial method: exact coefficients of F(t) and a root solver. Otherwise
// both candidates are guaranteed; which is faster depends on the tape's size
// (measurements in docs/methods.md):
// - on small tapes the interval method wins — one Jet<Interval> per segment
//   isolates roots in few steps (default scene 800×600, one thread: 1.19 s
//   against 1.76 s for sphere tracing; the ray suite: 19 µs per ray against
//   337 µs);
// - on large models sphere tracing wins: every method walks tapes pruned to
//   each segment's box, but sphere tracing needs fewer costly enclosures
//   (bear.vm, 543 clauses, 200×150 on 2 threads: 10.1 s against 12.3 s;
//   7.2 s against 3.2 s at 120×120 before the interval method pruned).
#include "zeroset/trace/choose_method.hpp"

#include "zeroset/expr/ray_polynomial.hpp"

namespace zeroset {

namespace {
/// Above this many clauses, sphere tracing's cheaper steps pay for their number.
constexpr std::size_t large_tape = 200;
}  // namespace

Method resolve_method(Method requested, const Tape& tape) {
    if (requested != Method::Auto) return requested;
    const int degree = polynomial_degree(tape);
    if (degree >= 1 && degree <= Polynomial::max_degree) return Method::Polynomial;  // exact F(t), survey §3.4
    return tape.clauses().size() > large_tape ? Method::Sphere : Method::Interval;
}

}  // namespace zeroset
