// Lipschitz bound from the interval gradient.
#include "zeroset/expr/lipschitz.hpp"

#include <limits>

namespace zeroset {

LipschitzBound lipschitz_bound(Evaluator<Dual<Interval>>& eval, const Box3& box) {
    const Dual<Interval> f = eval(Dual<Interval>::variable(Interval(box.lo.x, box.hi.x), 0),
                                  Dual<Interval>::variable(Interval(box.lo.y, box.hi.y), 1),
                                  Dual<Interval>::variable(Interval(box.lo.z, box.hi.z), 2));
    Interval sum_of_squares(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        const Interval g = f.g[axis];
        // An empty component where the value is defined means the enclosure
        // lost track of the derivative: no finite bound can be claimed.
        if (g.is_empty()) return {f.v, f.v.is_empty() ? 0.0 : std::numeric_limits<double>::infinity()};
        sum_of_squares = sum_of_squares + square(Interval(g.magnitude()));
    }
    double constant = sqrt(sum_of_squares).hi;
    if (constant != constant) constant = std::numeric_limits<double>::infinity();
    return {f.v, constant};
}

}  // namespace zeroset
