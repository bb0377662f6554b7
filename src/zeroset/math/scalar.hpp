// The tape's operations on plain floating-point numbers. Every number type of
// the evaluator (Interval, Dual, Jet, …) offers the same named functions, so a
// single evaluator template serves them all (DESIGN.md, "one tape, many number
// types"). The predicates at the end let generic code (Dual, Jet) pick a branch
// of min/max/abs, and tell where floor, tan and atan2 jump: a plain number
// always knows which side wins, and sits on one side of every jump.
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <optional>

namespace zeroset {

/// u = ε/2, the unit roundoff of doubles (Higham §2.2): the unit of every
/// rounding-error bound.
inline constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;

/// x/y as x·(1/y), with 1/y found once for several quotients or off a chain
/// of dependent steps: a rounding more than the division, and none on the
/// chain — except where 1/y overflowed (|y| below 2⁻¹⁰²⁴), as ∞·0 would be
/// NaN: there the division itself.
inline double times_inverse(double x, double y, double inverse_y) {
    return std::abs(inverse_y) < std::numeric_limits<double>::infinity() ? x * inverse_y : x / y;
}

template <std::floating_point F> inline F square(F a) { return a * a; }
template <std::floating_point F> inline F sqrt(F a) { return std::sqrt(a); }
template <std::floating_point F> inline F abs(F a) { return std::fabs(a); }
template <std::floating_point F> inline F exp(F a) { return std::exp(a); }
template <std::floating_point F> inline F log(F a) { return std::log(a); }
template <std::floating_point F> inline F sin(F a) { return std::sin(a); }
template <std::floating_point F> inline F cos(F a) { return std::cos(a); }
template <std::floating_point F> inline F tan(F a) { return std::tan(a); }
template <std::floating_point F> inline F atan(F a) { return std::atan(a); }
/// The angle of the point (x, y), in (−π, π]; the order of the arguments is C's.
template <std::floating_point F> inline F atan2(F y, F x) { return std::atan2(y, x); }
template <std::floating_point F> inline F floor(F a) { return std::floor(a); }
/// √(a² + b²) without overflow; its own op so that derivatives stay bounded
/// at 0, where sqrt(a² + b²) would divide 0 by 0 (see dual.hpp). Computed
/// as written (within 1.5 ulps) where a² + b² neither overflows nor loses
/// bits to underflow — several times faster than glibc's hypot, which
/// takes the rest (and ±∞, NaN).
template <std::floating_point F> inline F hypot(F a, F b) {
    constexpr F tiny = sizeof(F) == 4 ? F(0x1p-100) : F(0x1p-900);
    const F sum = a * a + b * b;
    if (sum >= tiny && sum <= std::numeric_limits<F>::max()) return std::sqrt(sum);
    if (a == F(0) && b == F(0)) return F(0);
    return std::hypot(a, b);
}
template <std::floating_point F> inline F pow(F a, F b) { return std::pow(a, b); }
/// a^n for an integer n, by repeated squaring (exact sign for negative a).
template <std::floating_point F> inline F powi(F a, int n) {
    unsigned m = n < 0 ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);  // |n|, even for INT_MIN
    F result = F(1);
    F base = a;
    while (m != 0) {
        if (m & 1u) result *= base;
        base *= base;
        m >>= 1;
    }
    return n < 0 ? F(1) / result : result;
}
/// The value as an int when it is exactly a moderately sized integer: then
/// pow(a, b) = powi(a, n), whose domain includes negative bases.
template <std::floating_point F> inline std::optional<int> integer_value(F a) {
    if (a == std::round(a) && std::abs(a) < F(1 << 30)) return static_cast<int>(a);
    return std::nullopt;
}
// NaN-propagating min/max: a NaN operand must not be silently dropped. (If
// b is NaN the comparison is false and b is returned.) Written without
// branches, so lane loops over them vectorise.
template <std::floating_point F> inline F min(F a, F b) {
    const F smaller = a < b ? a : b;
    return a != a ? a : smaller;
}
template <std::floating_point F> inline F max(F a, F b) {
    const F larger = a > b ? a : b;
    return a != a ? a : larger;
}

/// ln(eᵃ + eᵇ), the smooth maximum that soft blends are written with, as
/// max(a, b) + ln(1 + e^−|a−b|): no overflow where eᵃ would. Its own op (the
/// expression builder recognises ln of a sum of exps) so that its interval
/// and derivative enclosures stay tight (see interval.hpp).
template <std::floating_point F> inline F log_sum_exp(F a, F b) {
    const F m = max(a, b);
    if (m != m || std::isinf(m)) return m;  // NaN; +∞ wins; −∞ only when both are
    return m + std::log1p(std::exp(-std::fabs(a - b)));
}
/// ∂ log_sum_exp(a, b)/∂a = 1/(1 + e^(b−a)), in [0, 1] (½ where a and b are
/// the same infinity).
template <std::floating_point F> inline F log_sum_exp_weight(F a, F b) {
    const F x = b - a;
    return x != x ? F(0.5) : F(1) / (F(1) + std::exp(x));
}

/// True when a ≤ b holds for every value the numbers stand for.
template <std::floating_point F> inline bool certainly_le(F a, F b) { return a <= b; }
/// The smallest number that stands for both (only reached by NaN for scalars).
template <std::floating_point F> inline F hull(F a, F /*b*/) { return a; }
template <std::floating_point F> inline bool is_exact_zero(F a) { return a == F(0); }
/// A derivative of min or max where both sides are equal: the middle of the
/// two one-sided ones (for a number; an interval takes their hull). At
/// max(d, 0) with d = 0 — on the surface of a box's distance — that keeps
/// the gradient from vanishing.
template <std::floating_point F> inline F tie_derivative(F a, F b) { return F(0.5) * (a + b); }

/// True when floor, tan or atan2 may jump somewhere in the values the numbers
/// stand for (an integer, a pole, the cut x ≤ 0, y = 0): never for a point,
/// whose derivative is the one-sided value.
template <std::floating_point F> inline bool floor_may_jump(F /*a*/) { return false; }
template <std::floating_point F> inline bool tan_may_jump(F /*a*/) { return false; }
template <std::floating_point F> inline bool atan2_may_jump(F /*y*/, F /*x*/) { return false; }
/// ∂hypot/∂a = a/h at h = hypot(a, b): in [−1, 1]; 0 at the origin (a
/// subgradient there, as min/max/abs take one branch at a kink).
template <std::floating_point F> inline F hypot_slope(F a, F h) { return h == F(0) ? F(0) : a / h; }
/// n/h for the curvature term of hypot's second derivative, 0 at the origin.
template <std::floating_point F> inline F hypot_curvature(F n, F h) { return h == F(0) ? F(0) : n / h; }
/// The derivative of a function across a jump: unbounded, so that Lipschitz
/// bounds and monotonicity tests never step over it (never reached for a
/// plain number, which never straddles a jump).
template <std::floating_point F> inline F unbounded_derivative(F /*like*/) {
    return std::numeric_limits<F>::infinity();
}

}  // namespace zeroset
