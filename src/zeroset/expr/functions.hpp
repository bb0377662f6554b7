// Composite functions built from the op table's ops: GLSL's mod, clamp, mix
// and smoothstep (The OpenGL Shading Language 4.60, §8.3), and smooth CSG
// blends (Quilez, "smooth minimum", iquilezles.org/articles/smin), and
// Hoffman and Hopcroft's algebraic blend (survey §3.3). Being
// ordinary expressions, every number type evaluates them, and their interval
// and Lipschitz bounds are sound with nothing more to do.
#pragma once

#include "zeroset/expr/expr.hpp"

namespace zeroset {

/// a − b·⌊a/b⌋: the remainder with the sign of b (GLSL's mod); NaN for b = 0.
Expr mod(const Expr& a, const Expr& b);
/// min(max(a, lo), hi).
Expr clamp(const Expr& a, const Expr& lo, const Expr& hi);
/// a + (b − a)·t: a at t = 0, b at t = 1.
Expr mix(const Expr& a, const Expr& b, const Expr& t);
/// 0 for a ≤ e0, 1 for a ≥ e1, and the Hermite step s²(3 − 2s) with
/// s = (a − e0)/(e1 − e0) between (GLSL's smoothstep; e0 ≠ e1).
Expr smoothstep(const Expr& e0, const Expr& e1, const Expr& a);

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
