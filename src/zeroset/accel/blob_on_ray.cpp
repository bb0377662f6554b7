// A blob component as one ray sees it (Blob::on_ray's pieces): the cheap
// tests that the ray passes beside a centre or an axis, the ray mapped into
// a component's kernel space, the tube of reach about a cylinder's axis, and
// the part of the ray within a component's reach with its peak there.
#include "zeroset/accel/blob.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zeroset {

std::optional<KernelOnRay> Blob::part_on_ray(const Component& c, const MappedRay& q, Span part,
                                              const NearestApproach& approach) const {
    std::optional<ReachOnRay> reach;
    if (approach.a2 > 0.0) {
        reach = reach_on_ray(approach, c.reach);
    } else if (const double u = dot(q.q0, q.q0); u <= c.reach) {  // a ray along a cylinder's axis: the body's u is constant
        reach = ReachOnRay{{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, 0.0, u};
    }
    if (!reach) return std::nullopt;
    const double t_in = std::max(reach->span.t0, part.t0), t_out = std::min(reach->span.t1, part.t1);
    if (!(t_in <= t_out)) return std::nullopt;
    KernelOnRay k{q.q0, q.qd, q.q0_error, q.qd_error, c.strength, c.blobbiness, t_in, t_out,
                  static_cast<std::uint32_t>(&c - components_.data())};
    if (approach.a2 > 0.0) k.nearest = reach->nearest;
    if (!settings_.metaball_quadratics) {
        // The nearest approach found already serves unless a cylinder's part ends before it.
        const bool within = reach->nearest >= t_in && reach->nearest <= t_out;
        k.peak = within ? kernel_upper_bound_at(settings_, k, reach->nearest, reach->u_min)
                        : kernel_upper_bound(settings_, k, t_in, t_out);
    }
    return k;
}

bool Blob::passes_beside(const RaySizes& sizes, const Vec3d& point, double point_largest, double radius) {
    const Ray& ray = sizes.ray;
    const Vec3d offset = ray.origin - point;
    const double nearest = -dot(offset, ray.dir) * sizes.inverse_dir_square;
    const Vec3d closest = offset + nearest * ray.dir;
    // Both this and reach_on_ray round within a few units of these sizes;
    // 10⁻⁹ of them keeps every component the exact test could keep. (NaN
    // compares false: not beside.)
    const double keep =
        radius + 1e-9 * (radius + sizes.origin_largest + point_largest + std::abs(nearest) * sizes.dir_largest);
    return dot(closest, closest) > keep * keep;
}

Blob::MappedRay Blob::about_point(const RaySizes& sizes, const Component& c, const Vec3d& point, double point_largest) {
    const Ray& ray = sizes.ray;
    return {(ray.origin - point) * c.inverse_radius, ray.dir * c.inverse_radius,
            u4 * (sizes.origin_largest + point_largest) * c.inverse_radius, u4 * sizes.dir_largest * c.inverse_radius};
}

bool Blob::passes_beside_axis(const Ray& ray, double origin_length, double dir_length, const AxisLine& axis,
                              double radius) {
    // The lines' distance is |e·n|/|n|, e = o − p and n = d × w. Where
    // |n| ≥ 10⁻⁶·|d|·|w|, the rounding of e and n changes e·n by under
    // 10⁻⁹·(|o| + |p|)·|n| and |n|² by a part in 10⁹. The margin of
    // 10⁻⁸·(R + |o| + |p| + |w|) covers both, the exact tests' own rounding
    // (a few units of the same sizes), and the far end's offset from this
    // line (w = end − p rounded: a unit of |w|). Squares outside 2^±900 are
    // not decided here (an underflow would drop the margin or the angle
    // guard); NaN and ∞ compare false: not beside.
    const Vec3d normal = cross(ray.dir, axis.direction);
    const double normal_square = dot(normal, normal);
    const double sizes = dir_length * axis.direction_length;
    if (!well_scaled(normal_square) || !(normal_square > 1e-12 * sizes * sizes)) return false;
    const double apart = dot(ray.origin - axis.point, normal);
    const double keep = radius + 1e-8 * (radius + origin_length + axis.point_length + axis.direction_length);
    const double bound = keep * keep * normal_square;
    return well_scaled(keep * keep) && well_scaled(bound) && apart * apart > bound;
}

std::optional<Span> Blob::tube_on_ray(const MappedRay& across, double reach, const NearestApproach& approach) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const Span undecided{-infinity, infinity};
    const auto [a2, nearest, u_min, inverse_a2] = approach;
    if (!(a2 > 0.0)) return undecided;  // along the axis (or NaN)
    // The radius, wider by the coordinates' errors (twice over) at any t the
    // span can reach — within twice the plain radius's half-width of the
    // nearest approach — with their rounding here, and 10⁻⁹ of itself: the
    // parts' own tests round far less.
    const double plain = std::sqrt(reach) * (1.0 + 1e-9);
    const double reach_t = std::abs(nearest) + 2.0 * plain / std::sqrt(a2);
    const double error = across.q0_error + reach_t * across.qd_error +
                         4.0 * u4 * (max_abs(across.q0) + reach_t * max_abs(across.qd));
    if (!(error <= 0.5 * plain)) return undecided;  // the widening would pass the t it was worked out for
    const double radius = plain + 2.0 * error;
    if (u_min > radius * radius) return std::nullopt;
    const double half = std::sqrt((radius * radius - u_min) * inverse_a2) * (1.0 + 1e-9) + 1e-9 * std::abs(nearest);
    if (!(half >= 0.0) || !std::isfinite(nearest)) return undecided;  // NaN, or overflow
    return Span{nearest - half, nearest + half};
}

}  // namespace zeroset
