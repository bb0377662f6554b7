// The blob's field along a ray, segment by segment: its polynomial with a
// rounding bound (soft objects, POV-Ray) and its interval isolation
// (Blinn's Gaussian, metaballs).
#include "zeroset/trace/blob_segment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "zeroset/math/interval.hpp"
#include "zeroset/roots/closed_form.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"
#include "zeroset/roots/refine.hpp"
#include "zeroset/roots/subdivided_first_root.hpp"
#include "zeroset/trace/segment_stack.hpp"

namespace zeroset {

namespace {

/// γ_k = k·u / (1 − k·u) (Higham §3.1).
double gamma(int k) { return k * unit_roundoff / (1.0 - k * unit_roundoff); }

/// Σ_j |M_kj|·|v_j| (+ |m_k| for a point), the largest over the rows k.
double mapped_magnitude(const Mat4& m, const Vec3d& v, bool point) {
    double largest = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& r = m.m[k];
        const double row = std::abs(r[0] * v.x) + std::abs(r[1] * v.y) + std::abs(r[2] * v.z) + (point ? std::abs(r[3]) : 0.0);
        largest = std::max(largest, row);
    }
    return largest;
}

/// The three polynomials a component contributes to a segment, in the lanes
/// of one vector: its term K(u(τ)), the majorant with the inputs' errors, and
/// the plain majorant. Each lane takes the steps the three would take one by
/// one (GCC's and Clang's vector extension; lane 3 is unused).
using Lanes = double __attribute__((vector_size(32)));
using LanePolynomial = std::array<Lanes, BlobSegmentSolver::max_degree + 1>;

/// K(u(τ)) for a kernel polynomial c in u of `Size` coefficients and u(τ) a
/// quadratic, by Horner's rule over polynomials — lane 0 with c, the others
/// with |c|; writes 2·Size − 1 coefficients to out. The size is fixed at
/// compile time so that every loop unrolls (it was a fifth of a blob ray).
template <std::size_t Size>
void compose(const std::array<Lanes, Size>& c, const std::array<Lanes, 3>& u, LanePolynomial& out) {
    constexpr std::size_t n = 2 * Size - 1;
    std::array<Lanes, n> result{};
    result[0] = c[Size - 1];
    for (std::size_t i = Size - 1; i-- > 0;) {
        const std::size_t degree = 2 * (Size - 2 - i);  // result's before this step
        std::array<Lanes, n> product{};  // result · u
        for (std::size_t a = 0; a <= degree; ++a)
            for (std::size_t j = 0; j < 3; ++j) product[a + j] += result[a] * u[j];
        result = product;
        result[0] += c[i];
    }
    std::copy(result.begin(), result.end(), out.begin());
}

struct Enclosure {
    Interval value;  // f over the segment
    Interval slope;  // f′ over it
};

/// f and f′ over τ ∈ T about t_c, component by component.
Enclosure enclose(const BlobSegmentSettings& s, std::span<const KernelOnRay> kernels,
                  std::span<const std::uint32_t> active, double t_c, const Interval& tau) {
    Interval field(0.0), field_slope(0.0);
    for (const std::uint32_t i : active) {
        const KernelOnRay& k = kernels[i];
        const KernelArgument a = kernel_argument(k, t_c, tau.lo, tau.hi);
        const Interval K = kernel_over(s.kernel, a.u, k.blobbiness);
        // Blinn's slope is B·K: no second enclosure of the exponential.
        const Interval slope = s.kernel == BlobKernel::Blinn ? Interval(k.blobbiness) * K
                                                             : kernel_slope_over(s.kernel, a.u, k.blobbiness);
        field += k.strength * K;
        field_slope += k.strength * (slope * a.du);
    }
    return {s.threshold - field, -field_slope};
}

/// Pushes [ta, tb] onto the empty stack, front on top: cut at its
/// components' nearest approaches when one to three lie inside, else whole.
/// Every kernel decreases in u, and u is least at the nearest approach, so
/// between two of them each component's term is monotone, and where they
/// all have one sign of strength (the usual blob) so is f: its enclosures
/// then prove one root or none at once, where halving from the middle takes
/// several levels. Each piece costs an enclosure of all the components, so
/// with many (a molecule's segments) halving does better. The cuts only
/// choose where to split; the enclosures still decide.
void push_cut_at_nearest_approaches(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active,
                                    double ta, double tb, SegmentStack& segments) {
    constexpr std::size_t max_cuts = 3;
    std::array<double, max_cuts> cuts{};
    std::size_t count = 0;
    for (const std::uint32_t i : active) {
        const double t = kernels[i].nearest;
        if (!(t > ta && t < tb)) continue;
        if (count == max_cuts) {
            count = 0;  // too many: whole
            break;
        }
        std::size_t j = count++;  // sorted as they come: there are few
        for (; j > 0 && cuts[j - 1] > t; --j) cuts[j] = cuts[j - 1];
        cuts[j] = t;
    }
    if (count == 0) {
        segments.push(ta, tb, 0);
        return;
    }
    double end = tb;
    for (std::size_t j = count; j-- > 0;) {
        if (cuts[j] >= end) continue;  // the same approach twice
        segments.push(cuts[j], end, 1);
        end = cuts[j];
    }
    segments.push(ta, end, 1);
}

/// BlobSegmentSolver::polynomial for a kernel polynomial c in u of `Size`
/// coefficients (POV-Ray's 3, soft objects' 4).
template <std::size_t Size>
int kernel_polynomial(std::span<const double> c, double threshold, std::span<const KernelOnRay> kernels,
                      std::span<const std::uint32_t> active, double t_c, BlobSegmentSolver::Coefficients& value,
                      BlobSegmentSolver::Coefficients& radius) {
    constexpr std::size_t n = 2 * Size - 1;
    std::array<Lanes, Size> lane_c{};
    for (std::size_t i = 0; i < Size; ++i) lane_c[i] = Lanes{c[i], std::abs(c[i]), std::abs(c[i]), 0.0};
    value.fill(0.0);
    BlobSegmentSolver::Coefficients magnitude{}, perturbation{};
    LanePolynomial lanes{};
    for (const std::uint32_t i : active) {
        const KernelOnRay& k = kernels[i];
        const Vec3d q = k.q0 + t_c * k.qd;
        // The error of q's coordinates: the ray's map, then q0 + t_c·qd.
        // (Sums of |coordinates| bound the lengths without a square root each.)
        const double q_error =
            k.q0_error + std::abs(t_c) * k.qd_error + 2.0 * unit_roundoff * (norm1(k.q0) + std::abs(t_c) * norm1(k.qd));
        const Vec3d q_mag{std::abs(q.x), std::abs(q.y), std::abs(q.z)};
        const Vec3d d_mag{std::abs(k.qd.x), std::abs(k.qd.y), std::abs(k.qd.z)};
        const Vec3d q_up = q_mag + Vec3d{q_error, q_error, q_error};
        const Vec3d d_up = d_mag + Vec3d{k.qd_error, k.qd_error, k.qd_error};
        // u(τ) = |q + τ·qd|² for the term, the majorant with errors and the plain one.
        const std::array<Lanes, 3> u{Lanes{dot(q, q), dot(q_up, q_up), dot(q_mag, q_mag), 0.0},
                                     Lanes{2.0 * dot(q, k.qd), 2.0 * dot(q_up, d_up), 2.0 * dot(q_mag, d_mag), 0.0},
                                     Lanes{dot(k.qd, k.qd), dot(d_up, d_up), dot(d_mag, d_mag), 0.0}};
        compose<Size>(lane_c, u, lanes);
        const double s = std::abs(k.strength);
        for (std::size_t j = 0; j < n; ++j) {
            const Lanes& l = lanes[j];
            const double term = l[0], bound = l[1], plain = l[2];
            value[j] -= k.strength * term;
            magnitude[j] += s * bound;
            // The majorant's growth bounds what the inputs' errors do.
            perturbation[j] += s * (bound - plain);
        }
    }
    value[0] += threshold;
    magnitude[0] += threshold;
    const double g = gamma(2 * (24 + static_cast<int>(active.size())));
    for (std::size_t j = 0; j < n; ++j) radius[j] = (g * magnitude[j] + perturbation[j]) * (1.0 + 8.0 * unit_roundoff);
    for (std::size_t j = n; j < radius.size(); ++j) radius[j] = 0.0;
    return static_cast<int>(n);
}

}  // namespace

KernelArgument kernel_argument(const KernelOnRay& k, double t_c, double tau_a, double tau_b) {
    const double tau_max = std::max(std::abs(tau_a), std::abs(tau_b));
    const Vec3d qc = k.q0 + t_c * k.qd;
    // q's true coordinates lie within `spread` of qc + τ·qd: the ray's map, then q0 + t_c·qd.
    const double spread = k.q0_error + std::abs(t_c) * (k.qd_error + unit_roundoff * length(k.qd)) +
                          2.0 * unit_roundoff * length(qc) + tau_max * k.qd_error;
    double u_lo = 0.0, u_hi = 0.0, q_sum = 0.0, d_sum = 0.0, magnitude = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double c = qc[axis], d = k.qd[axis];
        // The ends' rounding (a product and a sum) and the subtraction of the margin: 4 units.
        const double e = (spread + 4.0 * unit_roundoff * (std::abs(c) + tau_max * std::abs(d))) * (1.0 + 4.0 * unit_roundoff);
        const double qa = c + tau_a * d, qb = c + tau_b * d;
        const double lo = std::min(qa, qb) - e, hi = std::max(qa, qb) + e;
        const double far = std::max(-lo, hi);
        u_lo += lo > 0.0 ? lo * lo : (hi < 0.0 ? hi * hi : 0.0);
        u_hi += far * far;
        q_sum += far;
        d_sum += std::abs(d);
        magnitude += std::abs(c * d) + tau_max * d * d;
    }
    // u′/2 = q·q_d = qc·qd + τ·|qd|² for the computed line: its range is its ends'. The true
    // one differs by the coordinates' spread times |q_d| and q's size times q_d's error.
    const double g_c = dot(qc, k.qd), g_d = dot(k.qd, k.qd);
    const double ga = g_c + tau_a * g_d, gb = g_c + tau_b * g_d;
    const double g_error = q_sum * k.qd_error + d_sum * spread + 3.0 * spread * k.qd_error + 8.0 * unit_roundoff * magnitude;
    // Sums of squares of three terms: well within 8 units relative; then the margins' own rounding.
    const double g_lo = std::min(ga, gb) - g_error, g_hi = std::max(ga, gb) + g_error;
    return {{u_lo * (1.0 - 8.0 * unit_roundoff), u_hi * (1.0 + 8.0 * unit_roundoff)},
            {2.0 * (g_lo - 4.0 * unit_roundoff * std::abs(g_lo)), 2.0 * (g_hi + 4.0 * unit_roundoff * std::abs(g_hi))}};
}

double mapping_error(const Mat4& m, const Vec3d& v, bool point) {
    return 4.0 * unit_roundoff * mapped_magnitude(m, v, point);
}

ValueAndDerivative blob_field_at(const BlobSegmentSettings& settings, std::span<const KernelOnRay> kernels,
                                 std::span<const std::uint32_t> active, double t) {
    double field = 0.0, slope = 0.0;
    for (const std::uint32_t i : active) {
        const KernelOnRay& k = kernels[i];
        const Vec3d q = k.q0 + t * k.qd;
        const KernelValue K = kernel_at(settings.kernel, dot(q, q), k.blobbiness);
        field += k.strength * K.value;
        slope += k.strength * K.slope * 2.0 * dot(q, k.qd);
    }
    return {settings.threshold - field, -slope};
}

double blob_field_upper_bound(const BlobSegmentSettings& settings, std::span<const KernelOnRay> kernels,
                              std::span<const std::uint32_t> active, double ta, double tb) {
    // First the components' peaks along the whole ray, worked out once a ray;
    // when they cannot reach T, the segment's own nearest approaches need not be.
    double peaks = 0.0;
    for (const std::uint32_t i : active) peaks += kernels[i].peak;
    peaks *= 1.0 + 1e-12;
    if (peaks < settings.threshold) return peaks;
    double bound = 0.0;
    for (const std::uint32_t i : active) bound += kernel_upper_bound(settings, kernels[i], ta, tb);
    return bound * (1.0 + 1e-12);
}

MetaballPiece metaball_piece(const KernelOnRay& k, double t) {
    const MetaballPieces pieces = metaball_pieces(k);
    int j = 0;
    while (j + 2 < pieces.count && pieces.ends[static_cast<std::size_t>(j + 1)] <= t) ++j;
    const double p0 = pieces.ends[static_cast<std::size_t>(j)], p1 = pieces.ends[static_cast<std::size_t>(j + 1)];
    const auto K = [&](double at) {
        const Vec3d q = k.q0 + at * k.qd;
        return kernel_value_at(BlobKernel::Metaball, dot(q, q), 0.0);
    };
    // The quadratic through K at the piece's ends and middle (exact where K = 1 − 3u).
    const double h = 0.5 * (p1 - p0), pm = p0 + h;
    const double k0 = K(p0), km = K(pm), k1 = K(p1);
    const double c2 = h > 0.0 ? (k0 - 2.0 * km + k1) / (2.0 * h * h) : 0.0;
    const double c1 = h > 0.0 ? (k1 - k0) / (2.0 * h) : 0.0;
    return {pm, km, c1, c2};
}

double kernel_value_on_ray(const BlobSegmentSettings& settings, const KernelOnRay& k, double t) {
    if (settings.metaball_quadratics) {
        const MetaballPiece p = metaball_piece(k, t);
        const double d = t - p.t_mid;
        return p.k_mid + p.c1 * d + p.c2 * d * d;
    }
    const Vec3d q = k.q0 + t * k.qd;
    return kernel_value_at(settings.kernel, dot(q, q), k.blobbiness);
}

int BlobSegmentSolver::polynomial(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active,
                                  double t_c, Coefficients& value, Coefficients& radius) const {
    const std::span<const double> c = blob_kernel_info(settings_.kernel).polynomial;
    if (c.size() == 3) return kernel_polynomial<3>(c, settings_.threshold, kernels, active, t_c, value, radius);
    return kernel_polynomial<4>(c, settings_.threshold, kernels, active, t_c, value, radius);
}

MetaballPieces metaball_pieces(const KernelOnRay& k) {
    const auto [a2, nearest, u_min, inverse_a2] = nearest_approach(k.q0, k.qd);
    if (!(u_min < 1.0 / 9.0)) return {{k.t_in, nearest, k.t_out, 0.0, 0.0}, 3};
    const double inner = std::sqrt(times_inverse(1.0 / 9.0 - u_min, a2, inverse_a2));
    return {{k.t_in, nearest - inner, nearest, nearest + inner, k.t_out}, 5};
}

HitStatus BlobSegmentSolver::roots(std::span<const KernelOnRay> kernels, std::span<const std::uint32_t> active,
                                   double ta, double tb, bool first_only, std::vector<double>& roots,
                                   TraceCounters& counters) const {
    if (settings_.metaball_quadratics) return quadratic_roots(kernels, active, ta, tb, first_only, roots, counters);
    if (blob_kernel_info(settings_.kernel).polynomial.empty())
        return interval_roots(kernels, active, ta, tb, first_only, roots, counters);
    return polynomial_roots(kernels, active, ta, tb, first_only, roots, counters);
}

HitStatus BlobSegmentSolver::polynomial_roots(std::span<const KernelOnRay> kernels,
                                              std::span<const std::uint32_t> active, double ta, double tb,
                                              bool first_only, std::vector<double>& roots,
                                              TraceCounters& counters) const {
    const double t_c = 0.5 * ta + 0.5 * tb;
    const double s0 = std::min(ta - t_c, 0.0), s1 = std::max(tb - t_c, 0.0);
    Coefficients value{}, radius{};
    const int n = polynomial(kernels, active, t_c, value, radius);
    ++counters.point_evaluations;
    for (int j = 0; j < n; ++j)
        if (!std::isfinite(value[static_cast<std::size_t>(j)])) return HitStatus::Failed;
    const std::span<const double> f(value.data(), static_cast<std::size_t>(n));
    const PolynomialEnclosure enclosure{f, std::span<const double>(radius.data(), static_cast<std::size_t>(n))};
    const auto at = [&](double s) { return std::clamp(t_c + s, ta, tb); };
    if (first_only) {  // as the polynomial method's first hit
        const PossibleRoot r = first_possible_root_subdividing(enclosure, s0, s1, settings_.tangent_width);
        counters.point_evaluations += static_cast<std::uint64_t>(r.evaluations);
        if (!r.found) return HitStatus::NoHit;
        roots.push_back(at(r.t));
        return HitStatus::Ok;
    }
    // Most segments that get here hold no root.
    if (provably_positive(enclosure, s0, s1)) return HitStatus::NoHit;
    std::array<double, max_degree> extrema{};
    const PolynomialRoots e = fast_polynomial_extrema(f, s0, s1, extrema);
    counters.point_evaluations += static_cast<std::uint64_t>(e.evaluations);
    const std::span<const double> turns(extrema.data(), static_cast<std::size_t>(e.count));
    std::array<double, 2 * max_degree + 2> found{};
    int evaluations = 0;
    const int count = possible_roots(enclosure, s0, s1, turns, found, evaluations);
    counters.point_evaluations += static_cast<std::uint64_t>(evaluations);
    for (int i = 0; i < count; ++i) roots.push_back(at(found[static_cast<std::size_t>(i)]));
    return count > 0 ? HitStatus::Ok : HitStatus::NoHit;
}

HitStatus BlobSegmentSolver::quadratic_roots(std::span<const KernelOnRay> kernels,
                                             std::span<const std::uint32_t> active, double ta, double tb,
                                             bool first_only, std::vector<double>& roots,
                                             TraceCounters& counters) const {
    // Σ of each component's quadratic piece over the segment, in τ = t − t_c.
    const double t_c = 0.5 * ta + 0.5 * tb;
    std::array<double, 3> f{settings_.threshold, 0.0, 0.0};
    for (const std::uint32_t i : active) {
        const KernelOnRay& k = kernels[i];
        const MetaballPiece p = metaball_piece(kernels[i], t_c);
        // About its middle, then moved to t_c: k_mid + c1·(τ + d) + c2·(τ + d)², d = t_c − t_mid.
        const double d = t_c - p.t_mid;
        f[0] -= k.strength * (p.k_mid + p.c1 * d + p.c2 * d * d);
        f[1] -= k.strength * (p.c1 + 2.0 * p.c2 * d);
        f[2] -= k.strength * p.c2;
        counters.point_evaluations += 3;
    }
    std::array<double, max_closed_form_degree> found{};
    const int count = closed_form_roots_in(f, ta - t_c, tb - t_c, found);
    const std::size_t before = roots.size();
    for (int i = 0; i < count; ++i) {
        const double tau = found[static_cast<std::size_t>(i)];
        // The pieces are the ray's own: a ray from a point a hair off the
        // surface (a shadow ray) may start inside by the approximation's
        // error. Its first hit is the first entry, where f falls through 0.
        if (first_only && f[1] + 2.0 * f[2] * tau > 0.0) continue;
        roots.push_back(std::clamp(t_c + tau, ta, tb));
        if (first_only) break;
    }
    return roots.size() > before ? HitStatus::Ok : HitStatus::NoHit;
}

HitStatus BlobSegmentSolver::interval_roots(std::span<const KernelOnRay> kernels,
                                            std::span<const std::uint32_t> active, double ta, double tb,
                                            bool first_only, std::vector<double>& roots,
                                            TraceCounters& counters) const {
    const double t_c = 0.5 * ta + 0.5 * tb;
    const auto point = [&](double t) {
        ++counters.point_evaluations;
        return blob_field_at(settings_, kernels, active, t);
    };
    const std::size_t found_before = roots.size();
    SegmentStack segments;
    push_cut_at_nearest_approaches(kernels, active, ta, tb, segments);
    for (long visited = 0; !segments.empty(); ++visited) {
        if (visited == settings_.max_segments || counters.over_limit()) return HitStatus::Failed;
        const Segment s = segments.pop();
        const Interval tau = Interval(s.a, s.b) - Interval(t_c);
        const Enclosure e = enclose(settings_, kernels, active, t_c, tau);
        ++counters.interval_evaluations;
        if (e.value.is_empty() || !std::isfinite(e.value.lo) || !std::isfinite(e.value.hi)) return HitStatus::Failed;
        if (!e.value.contains(0.0)) continue;  // Fig. 9, step 2: no root here
        if (!e.slope.is_empty() && !e.slope.contains(0.0)) {  // step 4: monotone, so one root at most
            const BracketPoint a{s.a, point(s.a)}, b{s.b, point(s.b)};
            if (is_inside(a.h.value) == is_inside(b.h.value)) continue;
            const BracketResult r = refine_root(point, a, b);
            roots.push_back(r.t);
            if (first_only) return HitStatus::Ok;
            continue;
        }
        // A near miss: the mean-value form f(m) + f′(T)·(T − m) excludes 0.
        const double mid = 0.5 * (s.a + s.b);
        const Interval at_mid =
            enclose(settings_, kernels, active, t_c, Interval(mid) - Interval(t_c)).value;
        if (!(at_mid + e.slope * (Interval(s.a, s.b) - Interval(mid))).contains(0.0)) continue;
        if (s.b - s.a > settings_.tangent_width && SegmentStack::above_resolution(s) && segments.can_split(s)) {
            segments.split(s, s.a);  // step 5: front half first
            continue;
        }
        // Still ambiguous at the finest width: a tangent root.
        roots.push_back(mid);
        if (first_only) return HitStatus::Ok;
    }
    return roots.size() > found_before ? HitStatus::Ok : HitStatus::NoHit;
}

}  // namespace zeroset
