// Composite functions built from the op table's ops: GLSL's mod, clamp, mix
// and smoothstep (The OpenGL Shading Language 4.60, §8.3), and smooth CSG
// blends (Quilez, "smooth minimum", iquilezles.org/articles/smin), and
// Hoffman and Hopcroft's algebraic blend (survey §3.3). Being
// ordinary expressions, every number type evaluates them, and their interval
// and Lipschitz bounds are sound with nothing more to do.
#pragma once

#include "zeroset/expr/expr.hpp"

namespace zeroset {

// The composites are written once, as templates over the number they
// build: Expr for a function of x, y, z, double for the scene parser, which
// evaluates calls on constants without making a node per step. Over doubles
// each step is the op table's, as Expr's constant folding takes it, so both
// give the same constant.
namespace composite {

template <class T> T mod(const T& a, const T& b) { return a - b * floor(a / b); }
template <class T> T clamp(const T& a, const T& lo, const T& hi) { return min(max(a, lo), hi); }
template <class T> T mix(const T& a, const T& b, const T& t) { return a + (b - a) * t; }
template <class T> T smoothstep(const T& e0, const T& e1, const T& a) {
    const T s = clamp<T>((a - e0) / (e1 - e0), T(0.0), T(1.0));
    return square(s) * (T(3.0) - T(2.0) * s);
}
template <class T> T ceil(const T& a) { return -floor(-a); }

}  // namespace composite

/// a − b·⌊a/b⌋: the remainder with the sign of b (GLSL's mod); NaN for b = 0.
inline Expr mod(const Expr& a, const Expr& b) { return composite::mod(a, b); }
/// min(max(a, lo), hi).
inline Expr clamp(const Expr& a, const Expr& lo, const Expr& hi) { return composite::clamp(a, lo, hi); }
/// a + (b − a)·t: a at t = 0, b at t = 1.
inline Expr mix(const Expr& a, const Expr& b, const Expr& t) { return composite::mix(a, b, t); }
/// 0 for a ≤ e0, 1 for a ≥ e1, and the Hermite step s²(3 − 2s) with
/// s = (a − e0)/(e1 − e0) between (GLSL's smoothstep; e0 ≠ e1).
inline Expr smoothstep(const Expr& e0, const Expr& e1, const Expr& a) { return composite::smoothstep(e0, e1, a); }
/// ⌈a⌉ = −⌊−a⌋ (no op of its own).
inline Expr ceil(const Expr& a) { return composite::ceil(a); }

// Smooth CSG on functions negative inside, with a blend radius k > 0 (a
// constant): the polynomial smooth minimum
//   smooth_union(a, b, k) = min(a, b) − max(k − |a − b|, 0)² / (4k).
// Where |a − b| ≥ k it is exactly min(a, b); elsewhere it is below min(a, b),
// by at most k/4 (at a = b), so the blend only adds material. Between, it is
// (a + b)/2 − k/4 − (a − b)²/(4k), whose gradient w·∇a + (1 − w)·∇b with
// w = (1 − (a − b)/k)/2 ∈ [0, 1] is a convex combination: a blend of
// 1-Lipschitz functions is 1-Lipschitz (so of distance bounds a distance
// bound). It is C¹ where a and b are.
Expr smooth_union(const Expr& a, const Expr& b, double k);
/// −smooth_union(−a, −b, k): at least max(a, b), and equal to it where |a − b| ≥ k.
Expr smooth_intersection(const Expr& a, const Expr& b, double k);
/// smooth_intersection(a, −b, k): a with b carved out, the edge rounded.
Expr smooth_difference(const Expr& a, const Expr& b, double k);

// Hoffman and Hopcroft's algebraic blend by the potential method (survey
// §3.3; Hoffman & Hopcroft 1985): C(g, h) = 0 for the parabola
// √(s/a) + √(t/b) = 1 squared twice, as 4gh/(ab) − (g/a + h/b − 1)², which
// touches h = 0 where g = a and g = 0 where h = b, and is negative in the
// fillet. A polynomial of degree at most 2·max(deg g, deg h) when g and h
// are polynomials. It is a fillet only when clipped to g ≤ a and h ≤ b and
// united with the two solids (docs/algebraic-blends.md).
Expr algebraic_blend(const Expr& g, const Expr& h, double a, double b);

}  // namespace zeroset
