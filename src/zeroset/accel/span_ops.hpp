// Roth's span-list arithmetic (survey §7; Roth 1982): the parts of a ray
// inside a union, intersection or difference of solids, from the sorted,
// disjoint span lists of the solids themselves. Boundaries keep the
// SurfaceRef of the solid they came from; in a difference, the subtracted
// solid's boundaries are flipped (its inside is the result's outside).
//
// Solids are closed sets and results are regularised: an intersection or a
// difference keeps no span of length 0 — two solids only touching, or a face
// shared by both, whose roots the two solids' methods may place an ulp or
// two apart (such slivers, shorter than 10⁻¹² of t, are dropped too) — while
// a union keeps them (a ray touching a solid tangentially).
#pragma once

#include "zeroset/accel/surface_ref.hpp"

namespace zeroset {

/// The union of any spans, in place: sorted by their start, the
/// overlapping ones merged (a group's spans are its children's, merged).
void merge_overlapping(SpanList& spans);

/// a ∩ b into out (cleared first). `a` and `b` are each sorted and disjoint.
void intersect(const SpanList& a, const SpanList& b, SpanList& out);

/// a − b into out (cleared first).
void subtract(const SpanList& a, const SpanList& b, SpanList& out);

}  // namespace zeroset
