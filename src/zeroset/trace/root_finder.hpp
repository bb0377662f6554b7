// RootFinder: one of the survey's ray-intersection methods over a RayFunction.
// Every method answers the same two questions — the first hit and all hits of
// a ray in a span [t0, t1] — and counts the evaluations it spends, so that
// methods can be compared on the same ray (DESIGN.md, "isolate, then refine").
//
// The first hit is the smallest t in the span where the ray is on or in the
// solid: the first root of H, or t0 itself when H(t0) ≤ 0 (the ray starts
// inside). All hits are the roots of H in the span, in increasing order.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "zeroset/math/box3.hpp"
#include "zeroset/trace/method.hpp"
#include "zeroset/trace/ray_function.hpp"

namespace zeroset {

enum class HitStatus {
    Ok,        // a hit was found
    NoHit,     // none in the span (guaranteed only for the guaranteed methods)
    Failed,    // the method gave up (Newton: zero derivative, iteration limit; NaN)
    Diverged,  // Newton's iterates left the span or blew up
};

std::string_view hit_status_name(HitStatus status);

struct HitResult {
    std::optional<double> t;
    HitStatus status = HitStatus::NoHit;
};

/// What a method did, for plots like the survey's Figures 4 and 10. Filled
/// only when a caller asks for it (never while rendering).
struct MethodLog {
    std::vector<double> newton_iterates;                    // Newton's t₀, t₁, … (Fig. 4)
    std::vector<std::array<double, 4>> interval_boxes;      // {t_lo, t_hi, H_lo, H_hi} (Fig. 10)
};

struct RootFinderSettings {
    /// Segments narrower than this that may still hold a root are reported as
    /// a (tangent) hit; the scene scale times 1e-10 by default.
    double tangent_width = 1e-10;
    /// Segments the isolating methods and sphere tracing may visit on one
    /// query before they give up (status Failed) — a guard against
    /// pathological rays, never reached on the ray suite.
    long max_segments = 1L << 20;
    /// Roots all_hits may collect on one query before it gives up (status
    /// Failed): far more than a ray can cross one object in any picture,
    /// and a bound on the span lists of CSG.
    std::size_t max_hits = 4096;
    /// Sphere tracing's hit tolerance before refinement.
    double sphere_epsilon = 1e-6;
    /// Samples of the span used by regula falsi and bisection to find brackets.
    int bracket_samples = 64;
    /// Newton's start; the span's t0 when absent.
    std::optional<double> newton_start;
    int newton_max_iterations = 64;
    /// The `polynomial` method's solver (closed forms fall back to Sturm above degree 4).
    PolynomialSolver polynomial_solver = PolynomialSolver::Fast;
    MethodLog* log = nullptr;
};

/// Tolerances for an object of size `scale` (SearchRegion::scale): sphere
/// tracing's ε far below a pixel at any sensible framing, the finest
/// isolation width far above double-precision noise.
RootFinderSettings settings_for_scale(double scale);

class RootFinder {
public:
    virtual ~RootFinder() = default;
    virtual HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) = 0;
    /// first_hit for a caller that knows the ray is outside the solid at t0
    /// (H(t0) > 0) — a later octree cell of a ray whose start was checked
    /// and whose earlier cells hold no root — so the start need not be
    /// evaluated again: the first root of H in the span. Where the claim is
    /// wrong (a pole before t0 changed H's sign without a root), sphere
    /// tracing answers t0, as first_hit would, and the isolating methods the
    /// span's first root. Methods that need H(t0) anyway keep first_hit's.
    virtual HitResult first_hit_from_outside(RayFunction& h, Span span, TraceCounters& counters) {
        return first_hit(h, span, counters);
    }
    /// Appends the roots in the span to `hits`; returns how the search ended.
    virtual HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) = 0;
};

/// The method's implementation for a tape. Method::Auto must be resolved by
/// the caller first (see choose_method).
std::unique_ptr<RootFinder> make_root_finder(Method method, const Tape& tape, const RootFinderSettings& settings);

}  // namespace zeroset
