// A proof, by interval arithmetic, that an object's bounds hold its surface:
// f > 0 all over the six faces of the box (so no part of the zero set
// reaches them, and a connected surface inside stays inside). Shared by the
// tests of deformed shapes and of the scenes that use them.
#pragma once

#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset::test {

/// True when interval arithmetic proves f > 0 on the region (possibly flat
/// along some axes), subdividing doubtful parts `depth` times.
inline bool proven_positive(Evaluator<Interval>& f, const Box3& region, int depth) {
    if (evaluate_box(f, region.lo, region.hi).lo > 0.0) return true;
    if (depth == 0) return false;
    const Vec3d mid = region.center();
    for (int octant = 0; octant < 8; ++octant) {
        Vec3d lo = region.lo, hi = region.hi;
        bool repeated = false;  // a flat axis splits into nothing: each part once
        for (int axis = 0; axis < 3; ++axis) {
            if (region.lo[axis] == region.hi[axis]) {
                repeated = repeated || (octant >> axis & 1);
                continue;
            }
            (octant >> axis & 1 ? lo : hi)[axis] = mid[axis];
        }
        if (!repeated && !proven_positive(f, {lo, hi}, depth - 1)) return false;
    }
    return true;
}

/// The faces (0 … 5: −x, +x, −y, +y, −z, +z) of the box on which f > 0 is
/// not proven to `depth` subdivisions; empty when the bounds hold.
inline std::vector<int> unproven_faces(const Expr& f, const Box3& box, int depth) {
    const Tape tape(f);
    Evaluator<Interval> eval(tape);
    std::vector<int> faces;
    for (int face = 0; face < 6; ++face) {
        Box3 side = box;
        const int axis = face / 2;
        side.lo[axis] = side.hi[axis] = face % 2 ? box.hi[axis] : box.lo[axis];
        if (!proven_positive(eval, side, depth)) faces.push_back(face);
    }
    return faces;
}

}  // namespace zeroset::test
