// The refinement phase of every method: a sign change of H over [a, b]
// brackets a root, which guarded Newton / bisection refine to full double
// precision (survey §4: "a combination of Newton's method and regula falsi
// can quickly refine the root to machine precision"). On a segment the
// interval or LG test proved monotone, that root is the only one.
#pragma once

#include <optional>

#include "zeroset/trace/ray_function.hpp"

namespace zeroset {

/// A root of H in [a, b], to full precision, when H changes sign there (or
/// vanishes at an end); nothing otherwise. With several roots in the
/// bracket, one of them.
std::optional<double> refine_sign_change(RayFunction& h, double a, double b, TraceCounters& counters);

}  // namespace zeroset
