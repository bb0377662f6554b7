// Shrinking by slabs: for each face, a galloping search for the thickest slab
// behind it that interval arithmetic (math/interval.hpp) proves outside, then
// bisection to the precision asked. Passes repeat because every face that
// moves narrows the slabs of the other axes, which tightens their proofs.
// A proof splits a cell across whichever side gives the halves the highest
// enclosures: on the piriform (4x⁴ − 4x³ + y² + z²) splitting the widest side
// left |y|, |z| ≤ 1.49 around a surface within 0.65, as x's dependency
// problem was never split away; trying all three sides leaves 0.81 for
// three times the evaluations a split, and half the cells (16 a proof)
// keep the cost where it was.
#include "zeroset/trace/search_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset {

namespace {

/// (1 − w)·a + w·b, which cannot overflow for finite a and b.
double mix(double a, double b, double w) { return (1.0 - w) * a + w * b; }

Vec3d centre(const Box3& box) {
    return {mix(box.lo.x, box.hi.x, 0.5), mix(box.lo.y, box.hi.y, 0.5), mix(box.lo.z, box.hi.z, 0.5)};
}

class OutsideProver {
public:
    OutsideProver(const Tape& tape, int max_cells) : eval_(tape), point_(tape), max_cells_(max_cells) {}

    /// True when f > 0 is proven all over the box with at most max_cells
    /// cells. A cell where f is undefined throughout (an empty enclosure) is
    /// not outside: it stays, for the methods to report the NaN. A point of
    /// the box with f ≤ 0 (or NaN) settles the question at once, so f is
    /// tried first at `witness`, a point of the box the caller expects to be
    /// inside, and at the centre of every cell before it is split.
    bool outside(const Box3& box, const Vec3d& witness) {
        if (!positive_at(witness)) return false;
        struct Cell {
            Box3 box;
            Interval f;
        };
        std::array<Cell, 64> stack;
        int size = 0, cells = 1;
        stack[size++] = {box, evaluate_box(eval_, box.lo, box.hi)};
        while (size > 0) {
            const Cell cell = stack[--size];
            const Interval f = cell.f;
            if (!f.is_empty() && f.lo > 0.0) continue;
            if (f.is_empty() || f.hi <= 0.0 || cells >= max_cells_ || size + 2 > static_cast<int>(stack.size()))
                return false;
            if (!positive_at(centre(cell.box))) return false;
            // Split across the side whose halves' enclosures come out highest
            // (the worse half's lower end): on a thin slab across loose
            // bounds, the widest side is rarely the one whose split helps.
            const auto lower = [](const Interval& i) { return i.is_empty() ? -std::numeric_limits<double>::infinity() : i.lo; };
            Cell best_low{}, best_high{};
            bool any = false;
            for (int axis = 0; axis < 3; ++axis) {
                const double middle = mix(cell.box.lo[axis], cell.box.hi[axis], 0.5);
                if (!(middle > cell.box.lo[axis] && middle < cell.box.hi[axis])) continue;  // as fine as doubles go
                Cell low{cell.box, {}}, high{cell.box, {}};
                low.box.hi[axis] = middle;
                high.box.lo[axis] = middle;
                low.f = evaluate_box(eval_, low.box.lo, low.box.hi);
                high.f = evaluate_box(eval_, high.box.lo, high.box.hi);
                if (!any || std::min(lower(low.f), lower(high.f)) > std::min(lower(best_low.f), lower(best_high.f))) {
                    best_low = low;
                    best_high = high;
                    any = true;
                }
            }
            if (!any) return false;  // every side as fine as doubles go
            stack[size++] = best_low;
            stack[size++] = best_high;
            ++cells;
        }
        return true;
    }

private:
    bool positive_at(const Vec3d& p) { return point_(p.x, p.y, p.z) > 0.0; }

    Evaluator<Interval> eval_;
    Evaluator<double> point_;
    int max_cells_;
};

/// The volume of `inner` over that of `outer` (which holds it), without
/// forming either volume (they may overflow); a flat side counts as 1.
double volume_ratio(const Box3& inner, const Box3& outer) {
    double ratio = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double width = outer.hi[axis] - outer.lo[axis];
        if (width > 0.0) ratio *= (inner.hi[axis] - inner.lo[axis]) / width;
    }
    return ratio;
}

/// Moves one face (side 0: lo, 1: hi) of `axis` inward past the thickest
/// slab proven outside; true when it moved by more than `precision` of the
/// width.
bool move_face(OutsideProver& prover, Box3& box, int axis, int side, double precision) {
    const double face = side == 0 ? box.lo[axis] : box.hi[axis];
    const double opposite = side == 0 ? box.hi[axis] : box.lo[axis];
    const auto cut = [&](double w) { return mix(face, opposite, w); };
    const auto clear = [&](double w) {  // the slab from the face to cut(w)
        Box3 slab = box;
        (side == 0 ? slab.hi[axis] : slab.lo[axis]) = cut(w);
        Vec3d deepest = centre(box);  // the middle of the slab's inner side: nearest the surface, likely
        deepest[axis] = cut(w);
        return prover.outside(slab, deepest);
    };
    // Gallop out from a thin slab, then bisect between the thickest slab
    // proven clear and the thinnest not.
    double cleared = 0.0, blocked = 1.0;
    for (double w = precision; w < 1.0; w *= 2.0) {
        if (!clear(w)) {
            blocked = w;
            break;
        }
        cleared = w;
    }
    while (blocked - cleared > precision) {
        const double w = 0.5 * (cleared + blocked);
        (clear(w) ? cleared : blocked) = w;
    }
    if (cleared < precision) return false;
    const double moved = cut(cleared);
    if (side == 0 ? !(moved < box.hi[axis]) : !(moved > box.lo[axis])) return false;
    (side == 0 ? box.lo[axis] : box.hi[axis]) = moved;
    return true;
}

}  // namespace

Box3 shrink_to_surface(const Tape& tape, const Box3& box, const ShrinkLimits& limits) {
    OutsideProver prover(tape, limits.cells_per_proof);
    if (prover.outside(box, centre(box))) return box;  // no surface here: nothing to shrink to
    Box3 shrunk = box;
    for (int pass = 0; pass < limits.max_passes; ++pass) {
        const Box3 before = shrunk;
        bool moved = false;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) moved |= move_face(prover, shrunk, axis, side, limits.precision);
        if (!moved || volume_ratio(shrunk, before) > limits.max_kept_volume) break;
    }
    return shrunk;
}

Bounds narrowed_to_clip(const Bounds& bounds, const std::optional<Expr>& clip, bool open) {
    if (!clip || !open || bounds.kind == Bounds::Kind::None) return bounds;
    const Box3 given = bounds.enclosing_box();
    const Box3 box = overlap(given, SearchRegion(Tape(*clip), bounds).box());
    const auto volume = [](const Box3& b) { return b.size().x * b.size().y * b.size().z; };
    return box.valid() && volume(box) < volume(given) ? Bounds::make_box(box) : bounds;
}

SearchRegion::SearchRegion(const Tape& tape, const Bounds& bounds) : bounds_(bounds) {
    if (bounds.kind == Bounds::Kind::None)
        throw std::invalid_argument("an implicit surface needs bounds (only a plane may go without: see HalfSpace)");
    const Box3 box = bounds.enclosing_box();
    if (!std::isfinite(box.diagonal()))
        throw std::invalid_argument("the bounds are too large for double precision: their diagonal overflows");
    // A margin of 10⁻⁶ of the object's size around the shrunk box (within
    // the given bounds): a face may have stopped right on the surface — a
    // floor's plane — and a ray entering there would start on it or, by
    // rounding, inside, taking the bounds' cut for the surface.
    const Box3 shrunk = shrink_to_surface(tape, box);
    const double margin = 1e-6 * shrunk.diagonal();
    for (int axis = 0; axis < 3; ++axis) {
        box_.lo[axis] = std::max(box.lo[axis], shrunk.lo[axis] - margin);
        box_.hi[axis] = std::min(box.hi[axis], shrunk.hi[axis] + margin);
    }
    scale_ = box_.diagonal();
}

std::optional<Span> SearchRegion::clip(const Ray& ray, double t_min, double t_max) const {
    const auto in_box = box_.clip(ray, t_min, t_max);
    if (!in_box || bounds_.kind == Bounds::Kind::Box) return in_box;
    return bounds_.clip(ray, in_box->t0, in_box->t1);
}

}  // namespace zeroset
