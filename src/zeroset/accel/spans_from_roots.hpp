// From a solid's surface roots along a ray to its inside spans — what every
// leaf with a root finder answers a CSG query with (survey §7). Between two
// consecutive events (the span's ends and the roots) the solid's sign is
// the same throughout, so the midpoint tells inside from outside; a root
// between two outside gaps is a tangent touch, a span of length 0, and one
// between two inside gaps neither opens nor closes a span.
#pragma once

#include <optional>
#include <span>

#include "zeroset/accel/surface_ref.hpp"

namespace zeroset {

/// Appends the spans of [t0, t1] to `out`. `roots` are sorted, merged and
/// strictly inside (t0, t1); `inside(t)` tells whether t is in the solid;
/// `hit(t, kind)` makes the boundary at t; the ends are of `start_kind` and
/// `end_kind` (Bounds where the solid's bounds cut it, Open at the query's ends).
template <class Inside, class MakeHit>
void spans_from_roots(std::span<const double> roots, double t0, double t1, BoundaryKind start_kind,
                      BoundaryKind end_kind, Inside&& inside, MakeHit&& hit, SpanList& out) {
    const std::size_t gaps = roots.size() + 1;
    const auto event = [&](std::size_t i) { return i == 0 ? t0 : (i <= roots.size() ? roots[i - 1] : t1); };
    const auto boundary = [&](std::size_t i) {
        return i == 0 ? start_kind : (i == gaps ? end_kind : BoundaryKind::Surface);
    };
    std::optional<Hit> open;
    bool previous_inside = true;  // so that t0 is never taken for a tangent root
    for (std::size_t i = 0; i < gaps; ++i) {
        const bool in = inside(0.5 * (event(i) + event(i + 1)));
        if (in && !open) open = hit(event(i), boundary(i));
        if (!in && open) {
            out.push_back({*open, hit(event(i), boundary(i))});
            open.reset();
        } else if (!in && !previous_inside) {  // a root between two outside gaps: a tangent touch
            const Hit touch = hit(event(i), BoundaryKind::Surface);
            out.push_back({touch, touch});
        }
        previous_inside = in;
    }
    if (open) out.push_back({*open, hit(event(gaps), boundary(gaps))});
}

}  // namespace zeroset
