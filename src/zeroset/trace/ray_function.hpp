// RayFunction: the surface seen along one ray, H(t) = f(x_o + t·x_d) (survey
// eqs. 7 and 13), in every form the intersection methods need — H at a point,
// H with H′ and H″ at a point (eqs. 19–21), and enclosures of H, H′, H″ over
// a whole segment of t (Fig. 9 needs H′, Fig. 11 needs H″).
//
// It is the one owner of everything that belongs to f along the ray: the
// tape and its evaluators, the tapes pruned to parts of the ray, the record
// of where f was NaN, and |x_d|. Methods never keep their own evaluators.
// |x_d| matters because rays reach a primitive through its transforms
// (eq. 36) with directions of any length: a tolerance or a distance bound
// given in space becomes one in t by dividing by |x_d|.
//
// Every evaluation is counted, so methods can be compared on the same ray.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/ray.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

class RayFunction {
public:
    explicit RayFunction(const Tape& tape);
    // It points into itself (the tape in use at each depth).
    RayFunction(const RayFunction&) = delete;
    RayFunction& operator=(const RayFunction&) = delete;

    /// Starts a new ray on the full tape.
    void set_ray(const Ray& ray);
    /// Makes `tape` — the full tape pruned to a region the ray's next
    /// queries stay in (an octree cell) — the tape those queries start
    /// from, as the full tape is after set_ray(); `can_prune` says whether
    /// it still has a min or max. It must outlive its use.
    void set_base_tape(const Tape& tape, bool can_prune);
    /// Makes the full tape the base again, as set_ray() does.
    void reset_base_tape() { set_base_tape(*tape_, can_prune_); }
    [[nodiscard]] const Ray& ray() const { return ray_; }
    /// Where along the ray the surface most likely is (NaN: nowhere in
    /// particular — the ray's point nearest f's origin), set after
    /// set_ray(): the polynomial method forms the ray's polynomial about it,
    /// where its rounding bound is least, and cuts a long span to the
    /// polynomial's root radius about it (an unbounded sheet's behind a
    /// gate shrinks to where the surface can be).
    void set_focus(double t) { focus_ = t; }
    [[nodiscard]] double focus() const { return focus_; }
    /// |x_d|, rounded up: a length ℓ in space is ℓ / dir_length() in t.
    /// Measured at its first use on a ray: the polynomial method never asks,
    /// and the three-way hypot cost its rays 3 % of their time.
    [[nodiscard]] double dir_length() const {
        if (!dir_length_known_) {
            dir_length_ = measured_dir_length();
            dir_length_known_ = true;
        }
        return dir_length_;
    }
    /// A length in space as a length in t along this ray.
    [[nodiscard]] double to_t(double length) const { return length / dir_length(); }

    /// H(t).
    double value(double t, TraceCounters& counters);
    /// H(t), H′(t), H″(t).
    Jet<double> jet(double t, TraceCounters& counters);
    /// An enclosure of H(t) at one t, free of rounding doubts (the point
    /// x_o + t·x_d itself is enclosed, not rounded).
    Interval enclose_value(double t, TraceCounters& counters);
    /// Enclosures of H, H′ and H″ over t ∈ [a, b].
    Jet<Interval> enclose(double a, double b, TraceCounters& counters);
    /// An enclosure of H′ over t ∈ [a, b]: of ∇f·x_d over the box around
    /// the segment, by a directional dual (math/dual.hpp) — about a third of
    /// a gradient's cost. Its magnitude is a Lipschitz bound of H there
    /// (eq. 30 along the ray), at most L·|x_d| with L bounding |∇f|. [0, 0]
    /// where H is undefined all over (nothing to step over); unbounded
    /// where the derivative's enclosure is lost. (enclose() bounds H′ too,
    /// but Jet<Interval> also carries H″.)
    Interval slope(double a, double b, TraceCounters& counters);

    /// Prunes the tape to the axis-aligned box around the ray over [a, b]
    /// (expr/tape_pruner.hpp): the tape at `depth` − 1 (the full tape for
    /// depth 0) is pruned into the tape at `depth`, and every evaluation
    /// walks it until the next prune() or set_ray(). Returns f over the box.
    /// A caller splitting the ray into nested segments prunes each one at its
    /// nesting depth, below SegmentStack::max_depth.
    Interval prune(std::size_t depth, double a, double b, TraceCounters& counters);
    /// Whether prune() can shorten the tape: it has a min or max.
    [[nodiscard]] bool can_prune() const { return base_can_prune_; }
    /// The box around the ray over [a, b], with the rounding of x_o + t·x_d enclosed.
    [[nodiscard]] Box3 segment_box(double a, double b) const;
    /// Goes back to the base tape: the full tape (valid everywhere) after
    /// set_ray(), or the one set_base_tape() gave.
    void use_full_tape() {
        if (bound_ != base_) use_tape(*base_);
    }

    /// Records that H is NaN at p (counted in TraceCounters::nan_evaluations).
    void note_nan(const Vec3d& p, TraceCounters& counters);
    /// Where H last evaluated to NaN.
    [[nodiscard]] const Vec3d& last_nan_point() const { return last_nan_point_; }

    [[nodiscard]] const Tape& tape() const { return *tape_; }

private:
    double checked(double value, double t, TraceCounters& counters) {
        if (value != value) note_nan(ray_.at(t), counters);
        return value;
    }
    /// Makes `tape` (the full tape or a pruned one) the one evaluations
    /// walk; `rewritten` when its clauses changed in place since it was last
    /// used.
    void use_tape(const Tape& tape, bool rewritten = false) {
        bound_ = &tape;
        if (rewritten) ++tape_version_;
    }

    /// An evaluator, bound to the tape in use when it is next used: most
    /// segments use one or two of the five, and a rebind loads every
    /// constant of the tape.
    template <class E>
    struct LazilyBound {
        explicit LazilyBound(const Tape& first) : evaluator(first), tape(&first) {}
        E& on(const Tape* in_use, std::uint64_t in_use_version) {
            if (tape != in_use || version != in_use_version) {
                evaluator.rebind(*in_use);
                tape = in_use;
                version = in_use_version;
            }
            return evaluator;
        }
        E evaluator;
        const Tape* tape;
        std::uint64_t version = 0;
    };

    const Tape* tape_;
    Vec3d last_nan_point_{};
    double focus_ = std::numeric_limits<double>::quiet_NaN();
    Ray ray_{};
    [[nodiscard]] double measured_dir_length() const;
    mutable double dir_length_ = 1.0;  // dir_length()'s, once known for this ray
    mutable bool dir_length_known_ = true;  // 1 until the first set_ray()
    LazilyBound<Evaluator<double>> point_;
    LazilyBound<Evaluator<Jet<double>>> jet_;
    LazilyBound<Evaluator<Interval>> value_enclosure_;
    LazilyBound<Evaluator<Jet<Interval>>> enclosure_;
    LazilyBound<Evaluator<DirectionalDual<Interval>>> slope_;
    std::optional<TapePruner> pruner_;  // made on the first prune()
    std::vector<Tape> pruned_;          // pruned_[d]: the tape pruned at depth d, if any
    std::vector<const Tape*> tape_at_;  // the tape in use at depth d: pruned_[d] or its parent's
    std::size_t valid_depths_ = 0;      // tape_at_[d] belongs to this ray's current segments for d < this
    /// Where value() last gave a number, and the number: the latest first.
    /// Two, so that a refinement of the bracket a march has just found
    /// (refine_bracket.hpp) takes H at neither end again.
    struct KnownValue {
        double t = std::numeric_limits<double>::quiet_NaN();
        double h = 0.0;
    };
    std::array<KnownValue, 2> known_{};
    [[nodiscard]] std::optional<double> known_value(double t) const {
        for (const KnownValue& k : known_)
            if (k.t == t) return k.h;
        return std::nullopt;
    }
    const Tape* bound_;                 // the tape evaluations walk
    std::uint64_t tape_version_ = 0;    // counts rewrites of pruned tapes in place
    const Tape* base_;                  // what depth 0 prunes from: the full tape or a cell's
    bool can_prune_;                    // the full tape has a min or max
    bool base_can_prune_;               // the base tape has one
};

}  // namespace zeroset
