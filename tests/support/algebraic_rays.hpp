// Rays for the accuracy study of the polynomial method (issue: algebraic
// surfaces): for a named surface scene, random rays through its bounds, and
// rays built around points of the surface — grazing it (tangent to the
// gradient there) and passing it at tiny offsets — each with its first hit
// computed by the MPFI oracle (support/mpfi_ray_oracle.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "support/mpfi_ray_oracle.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::test {

struct AlgebraicRay {
    Ray ray;
    Span span;
    std::optional<OracleRoot> reference;  // the first root in span
    bool grazing;                         // built tangent to the surface
};

/// `count` rays for the scene's first object (deterministic for a seed).
std::vector<AlgebraicRay> algebraic_rays(const Object& object, int count, unsigned seed);

}  // namespace zeroset::test
