// The polynomial method's accuracy on algebraic rays, per solver: how often
// it misses the first root (no hit, or a hit past it), how often it hits
// where the oracle proves no root, and |t − t_ref| / scale over the hits.
#pragma once

#include <vector>

#include "support/algebraic_rays.hpp"
#include "zeroset/trace/method.hpp"

namespace zeroset::test {

struct SolverAccuracy {
    int rays = 0;
    int misses = 0;
    int false_hits = 0;
    std::vector<double> errors;  // |t − t_ref| / scale, one per hit with a reference

    [[nodiscard]] double max_error() const;
    [[nodiscard]] double median_error() const;
};

/// A miss is a ray with a root and no hit, or a hit more than the tolerance
/// past the root: 1e-9 × scale for a simple root with |H′| ≥ 1e-6, else
/// 1e-7 × scale (a near-double root is only determined to about
/// rounding / |H′| in double precision).
SolverAccuracy measure_solver(const Object& object, const std::vector<AlgebraicRay>& rays, PolynomialSolver solver);

}  // namespace zeroset::test
