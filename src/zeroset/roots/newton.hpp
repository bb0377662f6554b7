// Newton's method (survey §2, eq. 22): t_{i+1} = t_i − H(t_i)/H′(t_i) from a
// start t₀, with no bracket. Fast near a simple root, but unpredictable: from
// nearby starts it converges to different roots or runs away (Fig. 4). It is
// kept to show why isolation matters, and records its iterates for plotting
// that figure. The trace layer refines isolated roots with refine_root
// (refine.hpp) instead, which cannot run away.
//
// It always stops within max_iterations evaluations. A runaway iteration is
// reported as soon as it leaves the domain (give the ray segment) or produces
// a non-finite t, H, H′ or step. On an unbounded domain a runaway may instead
// end Stalled, where H′ underflows to 0 far away, or at max_iterations.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "zeroset/math/interval.hpp"
#include "zeroset/roots/root_function.hpp"

namespace zeroset {

enum class NewtonStatus {
    Converged,      // H(t) = 0 exactly, or the last step was within tolerance
    Diverged,       // left the domain, or t, H, H′ or the step was not finite
    Stalled,        // H′(t) = 0 where H(t) ≠ 0: eq. 22 has no next point
    MaxIterations,  // max_iterations evaluations without converging
};

struct NewtonOptions {
    /// Evaluations of H and H′ allowed (one per iteration).
    int max_iterations = 64;
    /// Converged once a step is at most tolerance·max(1, |t|): relative for
    /// |t| ≥ 1, absolute below.
    double tolerance = 4.0 * std::numeric_limits<double>::epsilon();
    /// Leaving this range counts as divergence.
    Interval domain = Interval::entire();
    /// When set, receives t₀ and every later finite iterate, in order.
    std::vector<double>* iterates = nullptr;
};

struct NewtonResult {
    NewtonStatus status = NewtonStatus::MaxIterations;
    /// The last iterate: the root when converged, where it left the domain
    /// when it diverged that way.
    double t = 0.0;
    int evaluations = 0;
};

/// Newton's method on h, which returns H and H′ together, from t0.
template <DifferentiableFunction F>
NewtonResult newton(F&& h, double t0, const NewtonOptions& options = {}) {
    NewtonResult r{NewtonStatus::Diverged, t0, 0};
    if (!std::isfinite(t0) || !options.domain.contains(t0)) return r;
    if (options.iterates) options.iterates->push_back(t0);
    while (r.evaluations < options.max_iterations) {
        const ValueAndDerivative s = h(r.t);
        ++r.evaluations;
        if (!std::isfinite(s.value)) return r;
        if (s.value == 0.0) {
            r.status = NewtonStatus::Converged;
            return r;
        }
        if (s.derivative == 0.0) {
            r.status = NewtonStatus::Stalled;
            return r;
        }
        if (!std::isfinite(s.derivative)) return r;
        const double step = s.value / s.derivative;
        const double next = r.t - step;
        if (!std::isfinite(step) || !std::isfinite(next)) return r;
        r.t = next;
        if (options.iterates) options.iterates->push_back(next);
        if (!options.domain.contains(next)) return r;
        if (std::abs(step) <= options.tolerance * std::max(1.0, std::abs(next))) {
            r.status = NewtonStatus::Converged;
            return r;
        }
    }
    r.status = NewtonStatus::MaxIterations;
    return r;
}

}  // namespace zeroset
