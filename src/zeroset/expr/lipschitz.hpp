// A sound Lipschitz bound of f over a box (survey eq. 30): the norm of the
// interval enclosure of ∇f over the box (Dual<Interval>). No user ever has to
// guess a "max_gradient": sphere tracing (Fig. 12) steps by H/L with this L.
#pragma once

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {

struct LipschitzBound {
    Interval value;   // an enclosure of f over the box
    double constant;  // L ≥ |∇f| everywhere in the box (+∞ if unbounded)
};

/// L = sqrt(Σ max|∂f/∂xᵢ|²) over the box, rounded up. Where f is undefined
/// over part of the box, that part is ignored (the enclosure clips domains);
/// where the gradient cannot be enclosed, L is +∞.
LipschitzBound lipschitz_bound(Evaluator<Dual<Interval>>& eval, const Box3& box);

}  // namespace zeroset
