// F(t) = f∘r(t) as exact coefficients, for a polynomial f (survey §3.3–3.4,
// eqs. 8–11): the tape is evaluated once in Polynomial arithmetic with
// x = x_o + t·x_d, y and z alike — DESIGN.md's "one tape, many number types".
// The closed forms and polynomial solvers then work on the coefficients.
#pragma once

#include <optional>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/polynomial.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset {

/// The coefficients of F(t) along the ray, or nullopt when the tape is not
/// polynomial in x, y, z or F's degree exceeds Polynomial::max_degree.
/// Allocates the evaluator's slots: call once per ray and object, not per t.
std::optional<Polynomial> ray_polynomial(const Tape& tape, const Ray& ray);
/// The same with a caller's evaluator over the tape (no allocation per ray).
std::optional<Polynomial> ray_polynomial(Evaluator<Polynomial>& eval, const Ray& ray);

/// The structural total degree of f in x, y, z — an upper bound on the degree
/// of F along every ray — or −1 when f is not polynomial. A walk over the
/// clauses with one degree per slot (no ray involved, so the answer is the
/// same for every ray): constants are degree 0, and any op on constants is a
/// constant; + − take the max, × adds, square doubles, powi and pow with a
/// constant integral exponent n ≥ 0 multiply by n, division by a constant
/// keeps the degree. Anything else on a non-constant is not polynomial. This
/// accepts more than Tape::is_polynomial (division by constants, pow with an
/// integral constant exponent, functions of constants) — exactly what
/// ray_polynomial accepts. The degree saturates at Polynomial::max_degree + 1.
int polynomial_degree(const Tape& tape);

}  // namespace zeroset
