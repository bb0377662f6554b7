// A blob along one ray (survey §2, §3): each component the ray comes within
// reach of is a function of t — its kernel-space point q(t) = q₀ + t·q_d,
// u(t) = |q(t)|² a quadratic in t — and between the entry and exit events of
// those components the set in reach is fixed. On such a segment
// f(t) = T − Σ sᵢ·K(uᵢ(t)) is solved, first root first:
//
//   Exact polynomials (soft objects, POV-Ray): K is a polynomial in u, so f
//   is a polynomial in t of degree 6 or 4, formed about the segment's middle
//   with a proven bound on its rounding (Higham's γ over the majorant, plus
//   the error of mapping the ray into each kernel's space), then solved by
//   the guarded fast solver (roots/polynomial_enclosure.hpp): no root or
//   graze is missed that the bound can see.
//
//   Interval isolation (Blinn's Gaussian, metaballs): Mitchell's method
//   (Fig. 9) on the segment, with f and f′ enclosed kernel by kernel — u from
//   the ranges of q's coordinates, each linear in t, and every kernel is
//   monotone in u, so the enclosures are tight — a mean-value test for near
//   misses, and safeguarded Newton on monotone pieces. A segment is first
//   offered to a cheap bound (the components' peaks along the ray, then
//   their nearest approaches on it): most never reach T.
//
// Everything here works in fixed arrays and a caller's buffers: nothing is
// allocated per ray.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "zeroset/expr/blob_model.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/interval.hpp"
#include "zeroset/math/scalar.hpp"
#include "zeroset/roots/root_function.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {

/// One component as a ray sees it.
struct KernelOnRay {
    Vec3d q0;           // q(t) = q0 + t·qd, in the component's kernel space
    Vec3d qd;
    double q0_error;    // a bound on the error of q0's coordinates (mapping the ray's origin)
    double qd_error;    // the same for qd
    double strength;
    double blobbiness;
    double t_in;        // the ray is within reach, u(t) ≤ reach, on [t_in, t_out]
    double t_out;
    std::uint32_t component;
    /// kernel_upper_bound over [t_in, t_out]: blob_field_upper_bound's quick first try.
    double peak = 0.0;
    /// Where the ray comes nearest the component's center (or axis), as
    /// nearest_approach finds it: kernel_upper_bound starts there, so it
    /// must be set whenever qd ≠ 0. −∞ when every point is as near (a ray
    /// along a cylinder's axis, qd = 0).
    double nearest = -std::numeric_limits<double>::infinity();
};

/// Where the ray q(t) = q0 + t·qd in a component's kernel space is within
/// its reach, |q(t)|² ≤ reach — a hair wider, so that rounding never drops
/// a component where it still counts — with its nearest approach (t and u
/// there, as computed), or nothing when it never is.
struct ReachOnRay {
    Span span;
    double nearest;
    double u_min;
};
/// The ray q(t) = q0 + t·qd's nearest approach to the origin as computed:
/// a2 = |qd|², its t and u = |q(t)|² there (NaN or ∞ where a2 = 0), and
/// 1/a2 for the widths about it (found beside the approach, not after it:
/// a division off the chain of dependent steps every component pays).
struct NearestApproach {
    double a2;
    double nearest;
    double u_min;
    double inverse_a2;
};
/// With 1/|qd|² known already (a sphere's, from the ray's 1/|d|²), no
/// division at all; else one, beside the dot product. Any t serves the
/// bounds taken at the nearest approach, and the widths about it are far
/// wider than its rounding.
inline NearestApproach nearest_approach(const Vec3d& q0, const Vec3d& qd, double inverse_a2) {
    const double a2 = dot(qd, qd);
    const double nearest = times_inverse(-dot(q0, qd), a2, inverse_a2);
    const Vec3d closest = q0 + nearest * qd;
    return {a2, nearest, dot(closest, closest), inverse_a2};
}
inline NearestApproach nearest_approach(const Vec3d& q0, const Vec3d& qd) {
    return nearest_approach(q0, qd, 1.0 / dot(qd, qd));
}
/// reach_on_ray from the ray's nearest approach, found already (a
/// cylinder's tube test finds its body's).
/// Inline: returned through memory, the result was read back in wider
/// loads than it was written with, a stall on every component a ray meets.
inline std::optional<ReachOnRay> reach_on_ray(const NearestApproach& approach, double reach) {
    const auto [a2, nearest, u_min, inverse_a2] = approach;
    if (!(a2 > 0.0) || !(u_min <= reach)) return std::nullopt;
    const double half = std::sqrt(times_inverse(reach - u_min, a2, inverse_a2)) * (1.0 + 1e-12) + 1e-12 * std::abs(nearest);
    return ReachOnRay{{nearest - half, nearest + half}, nearest, u_min};
}
inline std::optional<ReachOnRay> reach_on_ray(const Vec3d& q0, const Vec3d& qd, double reach) {
    return reach_on_ray(nearest_approach(q0, qd), reach);
}

/// A bound on the rounding of each coordinate of m·v (m·(v, 1) for a point).
double mapping_error(const Mat4& m, const Vec3d& v, bool point);

/// u = |q|² and u′ = du/dt = 2 q·q_d of one component over τ ∈ [τa, τb]
/// about t_c (t = t_c + τ), with the errors of mapping the ray into its
/// space (q0_error, qd_error). Each coordinate of q is linear in τ, so its
/// range is that of its ends, and so is u′'s; worked in plain doubles with
/// one margin for the rounding, several times cheaper than an
/// outward-rounded interval operation each.
struct KernelArgument {
    Interval u, du;
};
KernelArgument kernel_argument(const KernelOnRay& k, double t_c, double tau_a, double tau_b);

/// What a segment search is given.
struct BlobSegmentSettings {
    BlobKernel kernel;
    double threshold;
    /// Segments narrower than this (in t) that may still hold a root are a (tangent) hit.
    double tangent_width;
    /// Interval segments one search may visit before it fails.
    long max_segments;
    /// Metaballs: solve the survey's quadratic pieces (metaball_pieces) instead of the exact kernel.
    bool metaball_quadratics = false;
};

/// Nishimura's approximation (survey §3.1): a metaball's contribution along
/// the ray in four quadratic pieces of t — between its entry, ρ = 1/3, its
/// nearest approach, ρ = 1/3 again and its exit. The inner pieces (ρ < 1/3,
/// K = 1 − 3u) are exact; the outer ones interpolate K at their ends and
/// middle. A ray that misses the inner ball has two pieces.
struct MetaballPieces {
    std::array<double, 5> ends;  // increasing: piece j is [ends[j], ends[j + 1]]
    int count;                   // of ends (3 or 5)
};
MetaballPieces metaball_pieces(const KernelOnRay& k);
/// The piece holding t, as K ≈ k_mid + c1·(t − t_mid) + c2·(t − t_mid)².
struct MetaballPiece {
    double t_mid, k_mid, c1, c2;
};
MetaballPiece metaball_piece(const KernelOnRay& k, double t);

/// One component's K at t as the solver sees it: the kernel, or with
/// metaball_quadratics its quadratic piece there.
double kernel_value_on_ray(const BlobSegmentSettings& settings, const KernelOnRay& k, double t);

/// f and f′ at t over the given components (those out of reach add 0), by
/// the exact kernel.
ValueAndDerivative blob_field_at(const BlobSegmentSettings& settings, std::span<const KernelOnRay> kernels,
                                 std::span<const std::uint32_t> active, double t);

// Inline, as the segments' bounds ask for them once a component and segment.
/// An upper bound on s·K(u) from a point of the ray already found nearest
/// the component: t and the computed u = |q0 + t·qd|² there, with the
/// error of mapping the ray into its space and of evaluating K; 0 for a
/// negative strength. Exact kernels only.
inline double kernel_upper_bound_at(const BlobSegmentSettings& settings, const KernelOnRay& k, double t, double u) {
    if (k.strength < 0.0) return 0.0;
    // |q| a little short by c, what the mapping and q0 + t·qd may be off
    // (each coordinate, so √3 of it in length), then K a little high:
    // every kernel decreases in u. Without a square root: (√u − c)² ≥
    // u − 2c·√u ≥ u − c·(u + 1), as 2√u ≤ u + 1; c is tiny, so the bound
    // is as tight. The factors of 1 ± units cover u's own rounding and this
    // line's, kernel_value_above K's. (The sums of |coordinates| bound
    // lengths the same way.)
    const double c = 1.7321 * (k.q0_error + std::abs(t) * k.qd_error + 4.0 * unit_roundoff * (norm1(k.q0) + std::abs(t) * norm1(k.qd)));
    const double shortest_square =
        std::max(0.0, (u * (1.0 - 8.0 * unit_roundoff) - c * (u + 1.0) * (1.0 + 4.0 * unit_roundoff)) * (1.0 - 4.0 * unit_roundoff));
    return k.strength * kernel_value_above(settings.kernel, shortest_square, k.blobbiness) * (1.0 + 2.0 * unit_roundoff);
}
/// The same over [ta, tb], from the component's nearest approach there:
/// k.nearest held to the segment, as u grows away from it.
inline double kernel_upper_bound(const BlobSegmentSettings& settings, const KernelOnRay& k, double ta, double tb) {
    if (k.strength < 0.0) return 0.0;
    // A ray along a cylinder's axis has qd = 0: u is the same everywhere (and [ta, tb] may be endless).
    const double nearest = dot(k.qd, k.qd) > 0.0 ? std::clamp(k.nearest, ta, tb) : 0.0;
    const Vec3d q = k.q0 + nearest * k.qd;
    return kernel_upper_bound_at(settings, k, nearest, dot(q, q));
}

/// An upper bound on Σ sᵢ·K(uᵢ) over [ta, tb] from the positive components'
/// nearest approach, with the error of mapping the ray into their spaces:
/// when it stays below T, the segment holds no root. Exact kernels only.
double blob_field_upper_bound(const BlobSegmentSettings& settings, std::span<const KernelOnRay> kernels,
                              std::span<const std::uint32_t> active, double ta, double tb);

/// The roots of f on one segment, increasing, by the kernel's exact method.
class BlobSegmentSolver {
public:
    explicit BlobSegmentSolver(const BlobSegmentSettings& settings) : settings_(settings) {}

    /// Appends the roots in [ta, tb] to `roots` (only the first when
    /// `first_only`); Failed when the interval search ran out of segments.
    HitStatus roots(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active, double ta,
                    double tb, bool first_only, std::vector<double>& roots, TraceCounters& counters) const;

    /// Soft objects and POV-Ray: f about t_c as a polynomial in τ = t − t_c
    /// with its rounding radius, ascending powers (degree ≤ 6); the count of
    /// coefficients is returned.
    static constexpr int max_degree = 6;
    using Coefficients = std::array<double, max_degree + 1>;
    int polynomial(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active, double t_c,
                   Coefficients& value, Coefficients& radius) const;

private:
    HitStatus polynomial_roots(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active, double ta,
                               double tb, bool first_only, std::vector<double>& roots, TraceCounters& counters) const;
    HitStatus quadratic_roots(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active, double ta,
                              double tb, bool first_only, std::vector<double>& roots, TraceCounters& counters) const;
    HitStatus interval_roots(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active, double ta,
                             double tb, bool first_only, std::vector<double>& roots, TraceCounters& counters) const;

    BlobSegmentSettings settings_;
};

}  // namespace zeroset
