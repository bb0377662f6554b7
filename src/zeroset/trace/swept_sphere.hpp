// Swept spheres (van Wijk 1984, survey §3.4): the solid a sphere fills as
// its centre runs along a polynomial space curve c(s), s ∈ [0, 1] — here a
// Bézier curve of degree 1 to 3 — while its radius r(s) varies linearly.
// The solid is the union of the spheres, so a ray meets it where it meets
// one of them.
//
// Along the ray x(t) = o + t·d, sphere s holds the points where
//   g(s, t) = |o + t·d − c(s)|² − r(s)² = A t² + 2 B(s) t + C(s) ≤ 0,
// A = d·d, B = d·(o − c), C = |o − c|² − r²: a polynomial in s and t. The
// ray meets sphere s where D(s) = B² − A·C ≥ 0, entering it at
// t_in(s) = (−B − √D)/A and leaving at t_out(s) = (−B + √D)/A. Over a
// stretch of s where D ≥ 0 the chords [t_in, t_out] move continuously, so
// their union is one span, from the least t_in to the greatest t_out. Those
// extremes lie at the stretch's ends or where t_in or t_out is stationary
// in s — where g = 0 and ∂g/∂s = 2 B′ t + C′ = 0 both hold. van Wijk
// eliminated s from that pair (a resultant), leaving a polynomial in t; we
// eliminate t instead, which is easier since ∂g/∂s is linear in t:
//   P(s) = A·C′² − 4·B·B′·C′ + 4·B′²·C = A·φ_in·φ_out,  φ = 2 B′ t + C′,
// of degree 4n − 2 for a curve of degree n (10 for cubics), and isolate its
// roots on [0, 1] by Descartes' rule of signs in the Bernstein basis (van
// Wijk used Sturm sequences; zeroset's lost a simple root of P here until
// its sequences dropped negligible leading terms, roots/sturm.hpp). A stationary t_in makes φ_in
// change sign, so P does too: each extreme is a root the solver isolates —
// except where B′ = C′ = 0, where φ_in and φ_out vanish together and P
// need not change sign, so B′'s roots (C′'s where B′ ≡ 0) are candidates
// too. The stretches themselves are bounded by the roots of D (degree 2n);
// a ray whose box test passes but whose D has only negative Bernstein
// coefficients misses every sphere and is rejected before any solving.
//
// Every candidate s (stretch ends, roots) names a sphere the ray really
// meets, so its chord lies inside the solid: a spurious candidate cannot
// move an entry later or an exit earlier, and the true extremes are among
// the candidates. As a safeguard for a root lost to rounding (a thin tube's
// P is tiny against its coefficients), the gaps between candidates are
// sampled for φ turning from negative to positive, and a turn found is
// bisected into another candidate. The first hit needs no step size or
// tolerance. A ray that only touches a sphere (a double root of D, a graze
// of the tube) gives a span of length 0, which counts as a hit when D there
// is 0 to within its rounding.
#pragma once

#include <array>

#include "zeroset/math/box3.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset {

/// The largest coordinate a segment's solid may reach (its polynomials hold
/// fourth powers of lengths).
inline constexpr double max_sweep_coordinate = 1e30;

/// One Bézier piece of a sweep: control points control[0 … degree], the
/// radius going linearly from radius_from (s = 0) to radius_to (s = 1).
class SweptSegment {
public:
    /// Throws std::invalid_argument for a degree outside 1 … 3, a point or
    /// radius that is not finite, a negative radius, two zero radii, or a
    /// solid that reaches past max_sweep_coordinate.
    SweptSegment(int degree, const std::array<Vec3d, 4>& control, double radius_from, double radius_to);

    [[nodiscard]] int degree() const { return degree_; }
    [[nodiscard]] const std::array<Vec3d, 4>& control() const { return control_; }
    [[nodiscard]] double radius_from() const { return r0_; }
    [[nodiscard]] double radius_to() const { return r1_; }

    /// The curve's point and the sphere's radius at s.
    [[nodiscard]] Vec3d center(double s) const;
    [[nodiscard]] double radius(double s) const { return r0_ + (r1_ - r0_) * s; }
    /// A box holding the solid: the control points' box (the curve stays in
    /// their hull) grown by the larger radius.
    [[nodiscard]] Box3 bounds() const;

    /// c(s) = Σ power[k]·sᵏ, k ≤ power_degree() ≤ degree() (leading terms at
    /// rounding level dropped).
    [[nodiscard]] const std::array<Vec3d, 4>& power() const { return power_; }
    [[nodiscard]] int power_degree() const { return power_degree_; }

private:
    int degree_;
    int power_degree_;
    std::array<Vec3d, 4> control_{};
    std::array<Vec3d, 4> power_{};
    double r0_, r1_;
};

/// Where a ray is inside a segment's solid: from t_enter to t_exit, entering
/// through the sphere at s_enter and leaving through the one at s_exit.
struct SweepSpan {
    double t_enter;
    double t_exit;
    double s_enter;
    double s_exit;
};

/// At most this many spans: D has at most 6 roots in [0, 1], so at most 4
/// stretches where it is positive and 7 points or stretches in all.
inline constexpr int max_sweep_spans = 8;

struct SweepSpans {
    std::array<SweepSpan, max_sweep_spans> spans{};
    int count = 0;
    /// Work, in polynomial evaluations (Sturm sequences, chords).
    int evaluations = 0;
};

/// The ray's spans inside the segment's solid over all t, sorted by
/// t_enter, disjoint (spans that overlap are merged).
SweepSpans sweep_spans(const SweptSegment& segment, const Ray& ray);

/// The s of the sphere that a point on the surface lies on: the s in
/// [0, 1] where |x − c(s)|² − r(s)² is least (0 on the surface). The outward
/// normal there is x − c(s), normalised (the envelope touches the sphere).
double sphere_through(const SweptSegment& segment, const Vec3d& x);

}  // namespace zeroset
