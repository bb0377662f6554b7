// Do an object's bounds cut through its solid? Where f < 0 on the bounds'
// boundary, a ray enters the solid at the bounds, and the renderer draws the
// bounds there — a flat cut the scene may not have meant. The search proves
// what it reports (f < 0 at a point of the boundary, evaluated exactly as a
// ray would) and stays cheap: interval evaluation rules out the patches of
// a face where f > 0, and only the others are split, to a fixed depth.
#pragma once

#include <optional>
#include <string>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/vec3.hpp"
#include "zeroset/trace/bounds.hpp"

namespace zeroset {

struct BoundsCut {
    Vec3d point;        // on the boundary, in the object's own space, with f(point) < 0
    std::string where;  // "the face x = 1.5", or "the bounding sphere"
};

/// A point of the boundary of `bounds` where f < 0, if the search finds one
/// (nothing for Bounds::Kind::None). At most a few thousand evaluations.
std::optional<BoundsCut> find_bounds_cut(const Tape& tape, const Bounds& bounds);

}  // namespace zeroset
