// F(t) = f∘r(t) as exact coefficients, for a polynomial f (survey §3.3–3.4,
// eqs. 8–11): the tape is evaluated once in Polynomial arithmetic with
// x = x_o + t·x_d, y and z alike — DESIGN.md's "one tape, many number types".
// This is the plain reference form; the polynomial method runs the compiled
// RayPolynomialProgram, which also bounds the coefficients' rounding and is
// checked against this one.
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
/// of F along every ray — or −1 when f is not polynomial, by the rules of
/// RayPolynomialProgram::compile (no ray involved, so the answer is the same
/// for every ray). This accepts more than Tape::is_polynomial (division by
/// nonzero constants, pow with an integral constant exponent, functions of
/// constants) — exactly what ray_polynomial accepts. A degree above
/// Polynomial::max_degree is reported as max_degree + 1.
int polynomial_degree(const Tape& tape);

}  // namespace zeroset
