// The singular points of an implicit surface — where f = 0 and ∇f = 0: the
// nodes of Kummer's, Barth's, Chmutov's and Endraß's surfaces, a cone's apex,
// Steiner's triple point and double lines — found numerically for any tape,
// with no coordinates known in advance, so that the algebraic accuracy study
// (algebraic_rays.hpp) can aim rays through them: along such a ray H has a
// double root or worse, the polynomial solvers' hardest case.
//
// A 64³ grid of cells covers the bounds' enclosing box (diagonal L). From
// every cell where the residual r = f² + L²|∇f|² at the centre is minimal
// among its 3 × 3 neighbours in some coordinate plane (true near an isolated
// node, and all along a singular curve), Levenberg–Marquardt drives (f, L·∇f)
// to 0, the Hessian from Jets along six directions. A point is kept when |f|
// and L·|∇f| are below 1e-9 × the RMS of f over the grid, it lies in the
// bounds and no kept point is within 1e-6 L of it. Deterministic; 10 to 80 ms
// for each scene of scenes/algebraic. The tolerance is relative to the whole
// box: bounds much larger than the surface's features loosen it. It also
// keeps the nodes that rounded coefficients (φ, √2 in Barth's and Endraß's
// surfaces) have turned into necks or gaps about 1e-8 × L wide: rays through
// them still see near-double roots.
#pragma once

#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/trace/bounds.hpp"

namespace zeroset::test {

/// The singular points of the zero set of `surface` inside `bounds`, in the
/// order found; at most `max_count` (a singular curve gives many), spread
/// over those found.
std::vector<Vec3d> surface_nodes(const Expr& surface, const Bounds& bounds, int max_count = 256);

}  // namespace zeroset::test
