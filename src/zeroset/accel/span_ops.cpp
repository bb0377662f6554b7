// Two-pointer merges over sorted span lists.
#include "zeroset/accel/span_ops.hpp"

#include <algorithm>
#include <cmath>

namespace zeroset {

namespace {

Hit flipped(Hit h) {
    h.surface.flipped = !h.surface.flipped;
    return h;
}

/// Appends [enter, exit] unless it is a sliver: no longer than the rounding
/// that tells two solids' roots on one face apart (12 digits of t; every
/// guaranteed method places a simple root to 15).
void push_proper(SpanList& out, const Hit& enter, const Hit& exit) {
    if (!std::isfinite(exit.t)) {  // a span running on to t = ∞ (a plane's): no sliver
        if (enter.t < exit.t) out.push_back({enter, exit});
        return;
    }
    const double sliver = 1e-12 * std::max(std::abs(enter.t), std::abs(exit.t));
    if (exit.t - enter.t > sliver) out.push_back({enter, exit});
}

}  // namespace

void merge_overlapping(SpanList& spans) {
    std::sort(spans.begin(), spans.end(), [](const InsideSpan& p, const InsideSpan& q) { return p.enter.t < q.enter.t; });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < spans.size(); ++i) {
        if (kept > 0 && spans[i].enter.t <= spans[kept - 1].exit.t) {
            if (spans[i].exit.t > spans[kept - 1].exit.t) spans[kept - 1].exit = spans[i].exit;
            continue;
        }
        spans[kept++] = spans[i];
    }
    spans.resize(kept);
}

void intersect(const SpanList& a, const SpanList& b, SpanList& out) {
    out.clear();
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const InsideSpan& p = a[i];
        const InsideSpan& q = b[j];
        const Hit& enter = p.enter.t >= q.enter.t ? p.enter : q.enter;
        const Hit& exit = p.exit.t <= q.exit.t ? p.exit : q.exit;
        push_proper(out, enter, exit);
        if (p.exit.t <= q.exit.t) ++i;
        else ++j;
    }
}

void subtract(const SpanList& a, const SpanList& b, SpanList& out) {
    out.clear();
    std::size_t j = 0;
    for (const InsideSpan& p : a) {
        Hit enter = p.enter;
        bool covered = false;  // the rest of p lies inside some span of b
        while (j < b.size() && b[j].exit.t < enter.t) ++j;
        for (std::size_t k = j; k < b.size() && b[k].enter.t <= p.exit.t; ++k) {
            const InsideSpan& q = b[k];
            if (q.enter.t > enter.t) push_proper(out, enter, flipped(q.enter));
            if (q.exit.t >= p.exit.t) {
                covered = true;
                break;
            }
            enter = flipped(q.exit);
        }
        if (!covered) push_proper(out, enter, p.exit);
    }
}

}  // namespace zeroset
