// SearchRegion: where the methods look for an object's surface — its bounds
// (survey §6.1), shrunk by interval analysis to the box the surface can be
// in. Each face of the bounds' box moves inward while the slab it sweeps is
// proven to hold only f > 0: outside the solid, where no ray can hit or start
// inside. So loose bounds cost little and change little: the span a ray is
// searched over, and the tolerances scaled to the object's size
// (settings_for_scale), come from the box interval analysis can prove about
// the surface, not from how generously its bounds were drawn — though where
// the proofs converge slowly (ShrinkLimits) that box stays larger than the
// surface's own. Where the bounds cut the solid (f ≤ 0 on a face), that
// face stays where it is.
#pragma once

#include <cstdint>
#include <optional>

#include "zeroset/expr/expr.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/trace/bounds.hpp"

namespace zeroset {

/// How far shrinking goes, and what it may spend: each proof splits its slab
/// into at most `cells_per_proof` boxes, each split trying all three sides
/// (six interval evaluations of f); a face stops within `precision` of the
/// box's width from where the proofs fail; at most `max_passes` rounds over
/// the six faces, each face taking at most 20 proofs, and no more passes once
/// a pass keeps more than `max_kept_volume` of the box's volume: where interval
/// bounds converge slowly (a quartic's tail in ±10⁴ bounds crept in by 15 %
/// a pass for 30 passes, 28 ms), later passes cost far more than they save.
/// A pass narrows loose bounds about 500-fold, so 128 passes reach from any
/// double range to any surface. A proof costs at most 1 + 6 × (cells_per_proof − 1) evaluations
/// (91), shrinking at most (1 + max_passes × 6 × 20) times that (1.4 M), about
/// 7 proofs when the bounds are already tight, and a few thousand
/// evaluations for bounds a thousand times too wide.
struct ShrinkLimits {
    int cells_per_proof = 16;
    double precision = 1.0 / 1024.0;
    int max_passes = 128;
    double max_kept_volume = 0.5;
};

/// The part of `box` outside which f > 0 is proven, to the limits above;
/// `box` itself when the surface cannot be in it at all or nothing is
/// proven. `tape` is f.
Box3 shrink_to_surface(const Tape& tape, const Box3& box, const ShrinkLimits& limits = {});

/// The bounds an object is searched in: an open object's narrowed to its
/// clip's solid — nothing is drawn where the clip is positive, so the box
/// that interval analysis proves holds the clip's solid holds all that is
/// drawn. Tight bounds matter: the object's size sets its tolerances and
/// its shadow rays' offset. The bounds themselves when that box is no
/// smaller, or the object is not open and clipped.
Bounds narrowed_to_clip(const Bounds& bounds, const std::optional<Expr>& clip, bool open);

class SearchRegion {
public:
    /// Throws std::invalid_argument for Bounds::Kind::None (no method could
    /// search an infinite span) and for bounds whose diagonal overflows.
    SearchRegion(const Tape& tape, const Bounds& bounds);

    /// The part of [t_min, t_max] where the ray is inside the bounds and the
    /// shrunk box, if any.
    [[nodiscard]] std::optional<Span> clip(const Ray& ray, double t_min, double t_max) const;
    /// The shrunk box.
    [[nodiscard]] const Box3& box() const { return box_; }
    /// The object's size, the shrunk box's diagonal: the scale of tolerances.
    [[nodiscard]] double scale() const { return scale_; }
    [[nodiscard]] const Bounds& bounds() const { return bounds_; }

private:
    Bounds bounds_;
    Box3 box_;
    double scale_;
};

}  // namespace zeroset
