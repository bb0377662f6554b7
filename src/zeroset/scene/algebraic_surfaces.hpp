// Classic algebraic surfaces by name — torus(R, r), kummer(mu2), barth_sextic()…
// — callable in scene expressions (docs/algebraic-surfaces.md). Each entry is
// a polynomial in x, y, z built from Expr, with its parameters, their
// defaults and its equation as text, so the parser can both build it and
// explain a wrong call. A surface may be given the point it is evaluated at,
// torus(1, 0.3, (x - 2, z, y)), which is how hand-written transforms compose.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/scene/value.hpp"

namespace zeroset {

struct AlgebraicParameter {
    std::string_view name;
    double default_value;
};

struct AlgebraicSurface {
    std::string_view name;
    std::vector<AlgebraicParameter> parameters;
    std::string_view equation;  // in the parameters' names, for docs and messages
    int degree;                 // in x, y, z at the default parameters
    /// f at the point p = (x, y, z) for the given parameter values (one per parameter).
    Expr (*build)(const ExprVector& p, std::span<const double> values);
    /// "" when the values are acceptable, else what is wrong with them.
    std::string (*check)(std::span<const double> values);
};

/// Every named surface, in documentation order.
std::span<const AlgebraicSurface> algebraic_surfaces();

/// The surface called `name`, or null.
const AlgebraicSurface* find_algebraic_surface(std::string_view name);

/// "torus(R = 1, r = 0.25 [, point])": how the surface is called.
std::string signature(const AlgebraicSurface& surface);

/// `values` followed by the defaults of the parameters they leave out.
std::vector<double> with_defaults(const AlgebraicSurface& surface, std::span<const double> values);

/// The surface at p with `values` (may be shorter than its parameter list:
/// the rest take their defaults). Assumes check() accepted them.
Expr build_algebraic_surface(const AlgebraicSurface& surface, std::span<const double> values, const ExprVector& p);

}  // namespace zeroset
