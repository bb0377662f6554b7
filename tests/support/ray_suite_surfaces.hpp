// The surfaces of the ray suite (tests/data/ray_suite.tsv), written as zeroset
// expressions. The suite's rows name a surface; the generator and the tests
// rebuild it from here, so both see exactly the same doubles.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/trace/bounds.hpp"

namespace zeroset::test {

struct SphereFeature {
    Vec3d center;
    double radius;
};

struct TorusFeature {  // around the z-axis, centred at the origin
    double major;
    double minor;
};

/// Parts of a surface known in closed form, from which rays with exact
/// special cases are built (tangent to a sphere part or a torus, through a
/// singular point). A sphere part's points may be covered by other parts.
struct SuiteFeatures {
    std::vector<SphereFeature> spheres;
    std::vector<TorusFeature> tori;
    std::vector<Vec3d> singular_points;  // on the surface, where ∇f = 0
};

struct SuiteSurface {
    std::string name;
    std::string description;
    Expr f;
    Bounds bounds;  // a box strictly containing the surface
    SuiteFeatures features;

    /// The scene's scale: the diagonal of its bounds.
    [[nodiscard]] double scale() const { return bounds.enclosing_box().diagonal(); }
};

/// Every surface of the suite, in the order the suite lists them.
const std::vector<SuiteSurface>& ray_suite_surfaces();

/// The surface called `name`; throws std::out_of_range for an unknown name.
const SuiteSurface& ray_suite_surface(std::string_view name);

}  // namespace zeroset::test
