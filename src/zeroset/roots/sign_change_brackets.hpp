// Brackets found by sampling: evaluate H at N evenly spaced points of
// [t₀, t₁] and report each pair of neighbouring samples on opposite sides of
// the surface (H ≤ 0 inside, so a sample with H = 0 counts as inside). This
// is the kind of ad hoc isolation the survey faults in Blinn's method (§2),
// and how the non-guaranteed bisection and regula falsi methods find their
// brackets. It is NOT guaranteed: two roots between neighbouring
// samples (a thin feature, a grazing ray) cancel and are missed, and so is
// any even number of them. The interval and Lipschitz methods exist for that.
//
// A sample where H is NaN carries no sign: no bracket has it as an end.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "zeroset/roots/bracket.hpp"
#include "zeroset/roots/root_function.hpp"

namespace zeroset {

/// Samples h at `samples` evenly spaced points from t0 to t1 (both included,
/// in order) and calls visit(Bracket) for each sign change, in order along t.
/// visit returns false to stop the sampling there (a first hit needs only the
/// first bracket). Returns the evaluations spent. Allocates nothing.
/// Throws std::invalid_argument unless t0 ≤ t1 are finite and samples ≥ 2.
template <ScalarFunction F, class Visit>
int for_each_sign_change(F&& h, double t0, double t1, int samples, Visit&& visit) {
    if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0 || samples < 2) {
        throw std::invalid_argument("sign-change sampling needs finite t0 <= t1 and at least 2 samples");
    }
    const double last = static_cast<double>(samples - 1);
    double previous_t = t0;
    double previous_h = static_cast<double>(h(t0));
    for (int i = 1; i < samples; ++i) {
        const double t = std::lerp(t0, t1, static_cast<double>(i) / last);  // exactly t1 at the end
        const double value = static_cast<double>(h(t));
        const bool signed_pair = !std::isnan(previous_h) && !std::isnan(value);
        if (signed_pair && is_inside(previous_h) != is_inside(value) && !visit(Bracket{previous_t, t})) return i + 1;
        previous_t = t;
        previous_h = value;
    }
    return samples;
}

struct SampledBrackets {
    std::vector<Bracket> brackets;  // in order along t
    int evaluations = 0;
};

/// Every sign-change bracket of h found by `samples` evenly spaced samples of [t0, t1].
template <ScalarFunction F>
SampledBrackets sign_change_brackets(F&& h, double t0, double t1, int samples) {
    SampledBrackets result;
    result.evaluations = for_each_sign_change(h, t0, t1, samples, [&](const Bracket& b) {
        result.brackets.push_back(b);
        return true;
    });
    return result;
}

}  // namespace zeroset
