// Substitution: f with x, y and z replaced by other expressions — how a
// deformation acts on a function (survey §9: the deformed surface is the zero
// set of f∘D⁻¹, so substitute D⁻¹'s components for x, y, z).
#pragma once

#include "zeroset/expr/expr.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

/// A point whose coordinates are expressions, e.g. D⁻¹(x, y, z).
using ExprPoint = Vec3<Expr>;

/// The point (x, y, z) itself.
ExprPoint coordinates();

/// f(p.x, p.y, p.z). Each distinct node of f is rebuilt once, by an
/// iterative walk (a chain of 100 000 nodes does not recurse), through the
/// ordinary builders: the result is hash-consed and constant-folded like any
/// other expression. f itself where p is (x, y, z).
Expr substitute(const Expr& f, const ExprPoint& p);

}  // namespace zeroset
