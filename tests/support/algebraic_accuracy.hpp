// The polynomial method's accuracy on algebraic rays, per solver, against
// the MPFI references: how often it misses the first root (no hit, or a hit
// past it), how often it reports a hit where no root is, and |t − t_ref| /
// scale over the hits.
//
// A hit where no root is must be a graze the arithmetic cannot resolve: the
// method reports the first t where F may vanish given its proven rounding
// bound, whose largest value over the span B is the method's resolution on
// the ray (PolynomialMethod::rounding_bound). Each such hit is checked
// against the exact |H(t)|, bounded with MPFI: worst_unresolved is the
// largest |H(t)| / B over them, and a value above 1 is a hit the bound does
// not excuse.
#pragma once

#include <vector>

#include "support/algebraic_rays.hpp"
#include "zeroset/trace/method.hpp"

namespace zeroset::test {

struct SolverAccuracy {
    int rays = 0;
    int misses = 0;
    int unresolved_hits = 0;       // a hit before the first root, or with none
    double worst_unresolved = 0.0;  // max |H(t)| / B over those hits
    std::vector<double> errors;    // |t − t_ref| / scale, one per hit on the first root

    [[nodiscard]] double max_error() const;
    [[nodiscard]] double median_error() const;
};

/// A ray that starts inside the solid (H(t0) < 0, proven) must hit at t0.
/// Otherwise a miss is a ray with a root and no hit, or a hit more than the
/// tolerance past the root: for a simple root, 1e-9 × scale or twice the
/// root's own uncertainty B/|H′(t)|, whichever is larger; for a multiple
/// or tangent root 1e-7 × scale (a near-double root is only determined to
/// about the square root of the rounding). A hit more than the tolerance
/// before the root is an unresolved hit, not a match.
///
/// With `lengthen` > 0 the method searches each ray's span run on by that
/// much (in t) past its end, as a ray through far larger bounds than the
/// surface's would be: the first root stays the reference's, and the
/// tolerances stay those of the ray's own span — a method may not lose
/// accuracy on the surface because the span reaches far beyond it.
SolverAccuracy measure_solver(const Object& object, const std::vector<AlgebraicRay>& rays, PolynomialSolver solver,
                              double lengthen = 0.0);

}  // namespace zeroset::test
