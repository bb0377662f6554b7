// A sign-change bracket, and the bookkeeping that bisection, regula falsi and
// refine_root share while they shrink one: which end lies inside (H ≤ 0, see
// root_function.hpp), when the bracket is small enough, when H was exactly 0
// or NaN, and a guard that forces a bisection step whenever three steps in a
// row fail to halve the bracket — so a hybrid is never slower than a small
// multiple of bisection, whatever the function.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "zeroset/roots/root_function.hpp"

namespace zeroset {

struct Bracket {
    double lo = 0.0;
    double hi = 0.0;
};

/// Halvings that take any finite bracket to adjacent doubles: its width is at
/// most 2·DBL_MAX < 2^1025 and doubles are at least 2^−1074 apart.
inline constexpr int max_bisections = 1025 + 1074;

enum class BracketStatus {
    Converged,       // the bracket is as small as asked, or H(t) is exactly 0
    InvalidBracket,  // an end is not finite; nothing was evaluated
    NoSignChange,    // both ends lie on the same side of the surface
    NotANumber,      // H gave NaN; the bracket is the last one without NaN
    MaxIterations,   // options.max_iterations interior evaluations were spent
};

struct BracketOptions {
    /// Evaluations allowed strictly inside the bracket (the two ends are not
    /// counted). A safety net that valid input does not reach: bisection needs
    /// at most max_bisections, and the hybrids bisect whenever they stop
    /// making progress (regula falsi halves the bracket at least once in
    /// every four steps).
    int max_iterations = 4 * max_bisections + 8;
    /// Stop once hi − lo ≤ x_tolerance. 0 means full precision: stop when no
    /// double lies strictly between lo and hi.
    double x_tolerance = 0.0;
};

struct BracketResult {
    BracketStatus status = BracketStatus::InvalidBracket;
    /// The root: a point where H is exactly 0, or else the end of the final
    /// bracket with the smaller |H| (on a tie, the inside end).
    double t = std::numeric_limits<double>::quiet_NaN();
    double value = std::numeric_limits<double>::quiet_NaN();  // H(t)
    /// The final bracket, {t, t} when H(t) is exactly 0.
    Bracket bracket;
    /// Every evaluation of H, the ends included.
    int evaluations = 0;
};

/// One end of a bracket: t, H(t) and, for a DifferentiableFunction, H′(t)
/// (NaN when only H is known).
struct BracketPoint {
    double t = 0.0;
    ValueAndDerivative h;
};

enum class BracketEnd { None, Lo, Hi };

/// A bracket being shrunk: the ends keep H on opposite sides of the surface.
class BracketSearch {
public:
    /// Starts on [a, b], given in either order: evaluates H at the lower end
    /// and, unless that settles it (an exact zero — the first hit along a ray —
    /// or NaN), at the upper end.
    template <class F>
    BracketSearch(F& h, double a, double b) {
        if (b < a) std::swap(a, b);
        lo_.t = a;
        hi_.t = b;
        if (!std::isfinite(a) || !std::isfinite(b)) {
            end(BracketStatus::InvalidBracket);
            return;
        }
        lo_.h = evaluate(h, a);
        if (settled(lo_)) return;
        hi_.h = evaluate(h, b);
        if (settled(hi_)) return;
        check_sign_change();
    }

    /// Starts on [lo.t, hi.t] (lo.t ≤ hi.t) with H already known at both
    /// ends, as the constructor above finds it: no evaluation.
    BracketSearch(const BracketPoint& lo, const BracketPoint& hi) : lo_(lo), hi_(hi) {
        if (!std::isfinite(lo.t) || !std::isfinite(hi.t) || hi.t < lo.t) {
            end(BracketStatus::InvalidBracket);
            return;
        }
        if (settled(lo_) || settled(hi_)) return;
        check_sign_change();
    }

    [[nodiscard]] const BracketPoint& lo() const { return lo_; }
    [[nodiscard]] const BracketPoint& hi() const { return hi_; }
    /// The end with the smaller |H|; on a tie, the inside end.
    [[nodiscard]] const BracketPoint& best() const {
        const double l = std::abs(lo_.h.value);
        const double u = std::abs(hi_.h.value);
        if (u < l || (u == l && is_inside(hi_.h.value))) return hi_;
        return lo_;
    }
    [[nodiscard]] double midpoint() const { return 0.5 * lo_.t + 0.5 * hi_.t; }  // no overflow at ±DBL_MAX
    [[nodiscard]] bool strictly_inside(double t) const { return lo_.t < t && t < hi_.t; }
    /// True when hi − lo ≤ x_tolerance or no double lies strictly between them.
    [[nodiscard]] bool small_enough(const BracketOptions& options) const {
        return hi_.t - lo_.t <= options.x_tolerance || !strictly_inside(midpoint());
    }
    /// True while the search should take another step.
    [[nodiscard]] bool running(const BracketOptions& options) const {
        return !ended_ && !small_enough(options) && iterations_ < options.max_iterations;
    }
    /// True when the last three steps did not halve the bracket: bisect next.
    [[nodiscard]] bool must_bisect() const { return stale_steps_ >= 3; }
    /// Lets a method count a step as progress although the bracket did not
    /// halve (refine_root: a Newton step at most half as long as the one before last).
    void note_progress() { stale_steps_ = 0; }

    /// Evaluates H at t, strictly inside the bracket, and moves the end on
    /// t's side of the surface to t. Returns the end that moved, or None when
    /// H(t) is exactly 0 or NaN, which ends the search.
    template <class F>
    BracketEnd step(F& h, double t) {
        const BracketPoint p{t, evaluate(h, t)};
        ++iterations_;
        if (settled(p)) return BracketEnd::None;
        const bool moves_lo = is_inside(p.h.value) == is_inside(lo_.h.value);
        (moves_lo ? lo_ : hi_) = p;
        if (hi_.t - lo_.t <= 0.5 * checkpoint_width_) {
            checkpoint_width_ = hi_.t - lo_.t;
            stale_steps_ = 0;
        } else {
            ++stale_steps_;
        }
        return moves_lo ? BracketEnd::Lo : BracketEnd::Hi;
    }

    [[nodiscard]] BracketResult result(const BracketOptions& options) const {
        BracketResult r;
        r.status = ended_ ? status_ : small_enough(options) ? BracketStatus::Converged : BracketStatus::MaxIterations;
        r.evaluations = evaluations_;
        r.bracket = {lo_.t, hi_.t};
        if (r.status != BracketStatus::InvalidBracket) {
            r.t = best().t;
            r.value = best().h.value;
        }
        return r;
    }

private:
    template <class F>
    ValueAndDerivative evaluate(F& h, double t) {
        ++evaluations_;
        if constexpr (DifferentiableFunction<F>) {
            return h(t);
        } else {
            return {static_cast<double>(h(t)), std::numeric_limits<double>::quiet_NaN()};
        }
    }
    void check_sign_change() {
        if (is_inside(lo_.h.value) == is_inside(hi_.h.value)) end(BracketStatus::NoSignChange);
        checkpoint_width_ = hi_.t - lo_.t;
    }
    void end(BracketStatus status) {
        ended_ = true;
        status_ = status;
    }
    /// Ends the search when H is exactly 0 at p (the bracket collapses onto
    /// p, a root) or NaN.
    bool settled(BracketPoint p) {
        if (p.h.value == 0.0) {
            lo_ = hi_ = p;
            end(BracketStatus::Converged);
        } else if (std::isnan(p.h.value)) {
            end(BracketStatus::NotANumber);
        }
        return ended_;
    }

    BracketPoint lo_;
    BracketPoint hi_;
    bool ended_ = false;  // the search ended early, with status_
    BracketStatus status_ = BracketStatus::Converged;
    double checkpoint_width_ = 0.0;  // the width the guard wants halved
    int stale_steps_ = 0;
    int iterations_ = 0;
    int evaluations_ = 0;
};

}  // namespace zeroset
