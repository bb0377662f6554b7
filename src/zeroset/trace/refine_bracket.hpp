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

/// The hit an isolating method reports for a segment [a, b] still undecided
/// at the finest width, where `slope` encloses H′: a tangent root at a —
/// unless no bound holds H′ there. Then H may jump (floor across an integer,
/// mod, tan at a pole, atan2 across its cut), its enclosure need not shrink
/// with the segment, and only a sign at the ends shows a root, as in sphere
/// tracing's ε-segments: a if H(a) ≤ 0 or H(b) ≤ 0 (or either is NaN), else
/// none — the root, if any, lies within the segment, reported at its left end
/// like a tangent root. And where the enclosure of H itself is unbounded
/// over the segment, the sign change may be a pole (−1/x at x = 0), which is
/// no root: see closes_in_on_a_pole.
/// True when H changes sign over [a, b] by a pole: the sign change, bisected
/// down to adjacent doubles (or an end where H is infinite), shows values
/// larger than H takes 16 segment widths off either end (a root shows
/// smaller ones, even one of 1/tan x where tan has its pole).
bool closes_in_on_a_pole(RayFunction& h, double a, double b, TraceCounters& counters);

std::optional<double> finest_segment_hit(RayFunction& h, double a, double b, const Jet<Interval>& e,
                                         TraceCounters& counters);

}  // namespace zeroset
