// Rays for the accuracy study of the polynomial method (issue: algebraic
// surfaces): for a named surface scene, random rays through its bounds; rays
// built around points of the surface — grazing it (tangent to the gradient
// there) and passing it at tiny offsets; and, where the surface has singular
// points (support/surface_nodes.hpp), rays through them from random
// directions — each with its first hit computed by the MPFI oracle
// (support/mpfi_ray_oracle.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "support/mpfi_ray_oracle.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::test {

enum class AlgebraicRayKind {
    Random,   // from outside through a random point of the bounds
    Grazing,  // tangent to the surface, or passing it at a tiny offset
    Node,     // through a singular point of the surface, as rounded to doubles
};

struct AlgebraicRay {
    Ray ray;
    Span span;
    std::optional<OracleRoot> reference;  // the first root in span
    AlgebraicRayKind kind;
};

/// `count` rays for the scene's first object (deterministic for a seed):
/// random and grazing in turn, or random, grazing and node in turn when the
/// surface has singular points in its bounds. A ray the oracle cannot decide
/// within its evaluation budget is replaced by the next one.
std::vector<AlgebraicRay> algebraic_rays(const Object& object, int count, unsigned seed);

}  // namespace zeroset::test
