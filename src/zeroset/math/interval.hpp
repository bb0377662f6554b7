// Interval: a closed range [lo, hi] that always contains the true result of
// the operation (the survey's §4, eqs. 25–29). Every bound is rounded outward:
// results are computed in round-to-nearest and then moved one or more ulps
// away (correctly rounded ops are off by at most half an ulp; glibc's exp, log,
// sin, cos, tan, atan, atan2 and pow by less than two, so those move by two).
// A sum or product that is exactly 0 stays 0 (rounding::exact_zero_down).
// tan over a pole, atan2 over its cut and floor over an integer jump: the
// value still encloses the range, and the *_may_jump predicates tell Dual and
// Jet that no derivative bounds the change there.
//
// Domains are clipped: sqrt/log/pow with a partly negative argument enclose
// the function over the part where it is defined. An interval entirely outside
// the domain yields the empty interval (NaN bounds), which contains nothing and
// propagates through later operations.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "zeroset/math/scalar.hpp"

namespace zeroset {

namespace rounding {
/// ±0, ±∞ and NaN, from their bits: the doubles whose bits past the sign
/// are all 0 or have every exponent bit set. One unsigned comparison finds
/// all three, so the usual case of a step takes a single, well predicted
/// branch (four branches, one on the sign, cost 7–8 % of bear.vm's render).
inline bool zero_infinite_or_nan(std::uint64_t bits) { return (bits << 1) - 1 >= 0xFFDF'FFFF'FFFF'FFFFu; }
/// The next double towards −∞ from a finite nonzero one: −1 in its bits
/// above 0, +1 below.
inline double step_down(std::uint64_t bits) { return std::bit_cast<double>(bits - 1 + ((bits >> 63) << 1)); }

/// The next double towards −∞ (std::nextafter without the libm call: this
/// runs for every bound of every interval op). ±∞ and NaN map to themselves
/// except +∞, which becomes the largest finite double — still a lower bound.
inline double down(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    if (zero_infinite_or_nan(bits)) [[unlikely]] {
        if (x == 0.0) return -std::numeric_limits<double>::denorm_min();
        if (x == std::numeric_limits<double>::infinity()) return std::numeric_limits<double>::max();
        return x;  // NaN, −∞
    }
    return step_down(bits);
}
/// The next double towards +∞.
inline double up(double x) { return -down(-x); }
inline double down2(double x) { return down(down(x)); }
inline double up2(double x) { return up(up(x)); }
/// The same for a result that is exact when it is 0: a sum or difference of
/// doubles (with gradual underflow, x + y rounds to 0 only when x = −y), or
/// a product of a zero factor. It stays 0 rather than stepping to a
/// subnormal: arithmetic on subnormals is many times slower on x86 (a
/// microcode assist per operation), and 0 + 0 would otherwise seed them.
inline double exact_zero_down(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    if (zero_infinite_or_nan(bits)) [[unlikely]] return x == 0.0 ? 0.0 : down(x);
    return step_down(bits);
}
inline double exact_zero_up(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    if (zero_infinite_or_nan(bits)) [[unlikely]] return x == 0.0 ? 0.0 : up(x);
    return -step_down(bits ^ (std::uint64_t{1} << 63));  // −down(−x)
}
/// The bounds of a product (detail::product): an exact 0 stays 0, and a
/// result below the smallest normal double in magnitude — an underflow —
/// widens to 0 or ±that normal, never to a subnormal: a chain of tiny
/// factors (exp falloffs multiplied together) would otherwise carry
/// subnormals into every later operation.
inline double product_down(double p) {
    constexpr double tiny = std::numeric_limits<double>::min();
    if (p > tiny || p <= -tiny || p != p) return down(p);
    return p >= 0.0 ? 0.0 : -tiny;
}
inline double product_up(double p) { return -product_down(-p); }
}  // namespace rounding

struct Interval {
    double lo = 0.0;
    double hi = 0.0;

    constexpr Interval() = default;
    /// A point interval. The double is taken as exact.
    constexpr explicit Interval(double v) : lo(v), hi(v) {}
    constexpr Interval(double lo_, double hi_) : lo(lo_), hi(hi_) {}

    static constexpr Interval entire() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    static constexpr Interval empty() {
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    }

    [[nodiscard]] constexpr bool is_empty() const { return !(lo <= hi); }
    [[nodiscard]] constexpr bool contains(double v) const { return lo <= v && v <= hi; }
    [[nodiscard]] constexpr bool contains(const Interval& o) const { return lo <= o.lo && o.hi <= hi; }
    [[nodiscard]] constexpr double width() const { return hi - lo; }
    [[nodiscard]] constexpr double mid() const { return 0.5 * lo + 0.5 * hi; }
    /// The largest absolute value in the interval.
    [[nodiscard]] constexpr double magnitude() const { return std::max(-lo, hi); }
};

inline Interval operator+(Interval a, Interval b) {
    return {rounding::exact_zero_down(a.lo + b.lo), rounding::exact_zero_up(a.hi + b.hi)};
}
inline Interval operator-(Interval a, Interval b) {
    return {rounding::exact_zero_down(a.lo - b.hi), rounding::exact_zero_up(a.hi - b.lo)};
}
inline Interval operator-(Interval a) { return {-a.hi, -a.lo}; }

namespace detail {
/// Product with 0 × ∞ = 0, the interval-arithmetic convention. A product
/// that underflows to 0 is not exact: it becomes the smallest subnormal of
/// its sign, so that a 0 here means exactly 0 (rounding::product_*).
inline double product(double a, double b) {
    if (a == 0.0 || b == 0.0) return 0.0;
    const double p = a * b;
    if (p != 0.0) return p;
    return (a < 0.0) != (b < 0.0) ? -std::numeric_limits<double>::denorm_min() : std::numeric_limits<double>::denorm_min();
}
}  // namespace detail

namespace detail {
/// The product where a bound is 0, below the smallest normal, or 0 × ∞.
inline Interval careful_product(Interval a, Interval b) {
    // A point 0 — the derivative of a constant, in the dual numbers, so the
    // commonest case here — times anything: the bounds the products below
    // give it (the upper one −0, from product_up).
    if ((a.lo == 0.0 && a.hi == 0.0) || (b.lo == 0.0 && b.hi == 0.0)) return {0.0, -0.0};
    const double p0 = product(a.lo, b.lo), p1 = product(a.lo, b.hi);
    const double p2 = product(a.hi, b.lo), p3 = product(a.hi, b.hi);
    return {rounding::product_down(std::min({p0, p1, p2, p3})), rounding::product_up(std::max({p0, p1, p2, p3}))};
}
}  // namespace detail

/// The four products, and their min and max stepped outward, without a
/// branch in the usual case where every product is a normal double or
/// infinite; zeros, underflows and 0 × ∞ take detail::careful_product.
inline Interval operator*(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
    const double lo = std::min({p0, p1, p2, p3}), hi = std::max({p0, p1, p2, p3});
    constexpr double tiny = std::numeric_limits<double>::min();
    if (std::abs(lo) > tiny && std::abs(hi) > tiny && !std::isnan(p0 + p1 + p2 + p3))
        return {rounding::down(lo), rounding::up(hi)};
    return detail::careful_product(a, b);
}

/// Division; a divisor that contains 0 gives the sound (extended) answer.
inline Interval operator/(Interval a, Interval b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    if (b.lo > 0.0 || b.hi < 0.0) {
        const double q0 = a.lo / b.lo, q1 = a.lo / b.hi, q2 = a.hi / b.lo, q3 = a.hi / b.hi;
        const double lo = std::min({q0, q1, q2, q3}), hi = std::max({q0, q1, q2, q3});
        if (lo != lo || hi != hi) return Interval::entire();  // ∞/∞
        return {rounding::down(lo), rounding::up(hi)};
    }
    if (b.lo == 0.0 && b.hi == 0.0) return Interval::empty();
    // The divisor touches or straddles 0: the quotient reaches ±∞ on the side(s)
    // where the divisor approaches 0.
    if (b.lo == 0.0 && a.lo >= 0.0) return {a.lo == 0.0 ? 0.0 : rounding::down(a.lo / b.hi), inf};
    if (b.lo == 0.0 && a.hi <= 0.0) return {-inf, a.hi == 0.0 ? 0.0 : rounding::up(a.hi / b.hi)};
    if (b.hi == 0.0 && a.lo >= 0.0) return {-inf, a.lo == 0.0 ? 0.0 : rounding::up(a.lo / b.lo)};
    if (b.hi == 0.0 && a.hi <= 0.0) return {a.hi == 0.0 ? 0.0 : rounding::down(a.hi / b.lo), inf};
    return Interval::entire();
}

inline Interval& operator+=(Interval& a, Interval b) { return a = a + b; }
inline Interval& operator-=(Interval& a, Interval b) { return a = a - b; }
inline Interval& operator*=(Interval& a, Interval b) { return a = a * b; }

inline Interval operator+(Interval a, double b) { return a + Interval(b); }
inline Interval operator+(double a, Interval b) { return Interval(a) + b; }
inline Interval operator-(Interval a, double b) { return a - Interval(b); }
inline Interval operator-(double a, Interval b) { return Interval(a) - b; }
inline Interval operator*(Interval a, double b) { return a * Interval(b); }
inline Interval operator*(double a, Interval b) { return Interval(a) * b; }
inline Interval operator/(Interval a, double b) { return a / Interval(b); }
inline Interval operator/(double a, Interval b) { return Interval(a) / b; }

/// Tight square: starts at 0 when the argument contains 0, and rounding down
/// stops at 0 (else powi(a, −2) = 1/square(a) would see a divisor straddling 0).
inline Interval square(Interval a) {
    if (a.is_empty()) return a;
    if (a.lo >= 0.0) return {std::max(0.0, rounding::down(a.lo * a.lo)), rounding::up(a.hi * a.hi)};
    if (a.hi <= 0.0) return {std::max(0.0, rounding::down(a.hi * a.hi)), rounding::up(a.lo * a.lo)};
    const double m = std::max(-a.lo, a.hi);
    return {0.0, rounding::up(m * m)};
}

inline Interval abs(Interval a) {
    if (a.lo >= 0.0 || a.is_empty()) return a;
    if (a.hi <= 0.0) return -a;
    return {0.0, std::max(-a.lo, a.hi)};
}

inline Interval sqrt(Interval a) {
    if (a.is_empty() || a.hi < 0.0) return Interval::empty();
    const double lo = a.lo <= 0.0 ? 0.0 : std::max(0.0, rounding::down(std::sqrt(a.lo)));
    return {lo, rounding::up(std::sqrt(a.hi))};
}

namespace detail {
/// For x < −708.3, eˣ lies below 2.5·10⁻³⁰⁸, just above the smallest normal
/// double; its bounds there are 0 and 2.5·10⁻³⁰⁸, never a subnormal (as
/// for products).
inline constexpr double exp_normal_edge = -708.3;
/// A lower bound of eˣ.
inline double exp_below(double x) { return x < exp_normal_edge ? 0.0 : std::max(0.0, rounding::down2(std::exp(x))); }
/// An upper bound of eˣ.
inline double exp_above(double x) { return x < exp_normal_edge ? 2.5e-308 : rounding::up2(std::exp(x)); }
}  // namespace detail

inline Interval exp(Interval a) {
    if (a.is_empty()) return a;
    return {detail::exp_below(a.lo), detail::exp_above(a.hi)};
}

inline Interval log(Interval a) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (a.is_empty() || a.hi < 0.0) return Interval::empty();
    const double lo = a.lo <= 0.0 ? -inf : rounding::down2(std::log(a.lo));
    const double hi = a.hi == 0.0 ? -inf : rounding::up2(std::log(a.hi));
    return {lo, hi};
}

namespace detail {
/// Range of a 2π-periodic function g over [lo, hi], where g peaks (value 1)
/// at `peak` + 2kπ and bottoms out (value −1) at `peak` + π + 2kπ.
template <class G>
Interval periodic_range(Interval a, G g, double peak) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    if (a.is_empty()) return a;
    // Beyond ~2^40 the period is not resolved well in double: answer the whole range.
    if (!(a.width() < two_pi) || std::abs(a.lo) > 1e12 || std::abs(a.hi) > 1e12) return {-1.0, 1.0};
    double lo = std::min(g(a.lo), g(a.hi));
    double hi = std::max(g(a.lo), g(a.hi));
    // Is there a peak / trough inside? Checked with a small margin, so a peak
    // that is missed only by rounding still counts (the bound stays sound).
    const double margin = 1e-12 * (1.0 + std::abs(a.lo) + std::abs(a.hi));
    const double k_peak = std::ceil((a.lo - margin - peak) / two_pi);
    if (peak + k_peak * two_pi <= a.hi + margin) hi = 1.0;
    const double trough = peak + std::numbers::pi;
    const double k_trough = std::ceil((a.lo - margin - trough) / two_pi);
    if (trough + k_trough * two_pi <= a.hi + margin) lo = -1.0;
    return {std::max(-1.0, rounding::down2(lo)), std::min(1.0, rounding::up2(hi))};
}
}  // namespace detail

inline Interval sin(Interval a) {
    return detail::periodic_range(a, [](double v) { return std::sin(v); }, std::numbers::pi / 2);
}
inline Interval cos(Interval a) {
    return detail::periodic_range(a, [](double v) { return std::cos(v); }, 0.0);
}

namespace detail {
/// π rounded down and up: the double nearest π is below it.
inline constexpr double pi_down = std::numbers::pi;
inline constexpr double pi_up = 3.1415926535897936;  // the next double above π
static_assert(pi_up > pi_down);
inline constexpr double half_pi_up = pi_up / 2.0;

/// True when a may hold a pole π/2 + kπ of tan, or is too wide or too far
/// out to tell (checked with the margin periodic_range uses, so a pole
/// missed only by rounding still counts).
inline bool may_hold_tan_pole(Interval a) {
    if (a.lo == a.hi) return false;  // a double is never a pole
    if (!(a.width() < pi_down)) return true;
    const double margin = 1e-12 * (1.0 + std::abs(a.lo) + std::abs(a.hi));
    const double half_pi = std::numbers::pi / 2.0;
    const double k = std::ceil((a.lo - margin - half_pi) / std::numbers::pi);
    return half_pi + k * std::numbers::pi <= a.hi + margin;
}
}  // namespace detail

/// tan: increasing between its poles; ℝ over an interval that may hold one.
inline Interval tan(Interval a) {
    if (a.is_empty()) return a;
    if (detail::may_hold_tan_pole(a)) return Interval::entire();
    const double lo = rounding::down2(std::tan(a.lo)), hi = rounding::up2(std::tan(a.hi));
    if (!(lo <= hi)) return Interval::entire();  // a pole after all (cannot happen with the margin)
    return {lo, hi};
}
inline bool tan_may_jump(Interval a) { return !a.is_empty() && detail::may_hold_tan_pole(a); }

/// atan: increasing, within (−π/2, π/2).
inline Interval atan(Interval a) {
    if (a.is_empty()) return a;
    return {std::max(-detail::half_pi_up, rounding::down2(std::atan(a.lo))),
            std::min(detail::half_pi_up, rounding::up2(std::atan(a.hi)))};
}

/// atan2(y, x) over the box y × x. Where the box holds the origin or meets the
/// cut (x ≤ 0, y = 0, where the angle jumps from π to −π — a signed zero
/// picks either side) it is [−π, π]; elsewhere the angle is continuous on the
/// box and, the box being convex and away from the origin, takes its extremes
/// at the corners.
inline Interval atan2(Interval y, Interval x) {
    if (y.is_empty() || x.is_empty()) return Interval::empty();
    if (y.contains(0.0) && x.lo <= 0.0) return {-detail::pi_up, detail::pi_up};
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double yc : {y.lo, y.hi}) {
        for (const double xc : {x.lo, x.hi}) {
            const double angle = std::atan2(yc, xc);
            lo = std::min(lo, angle);
            hi = std::max(hi, angle);
        }
    }
    return {std::max(-detail::pi_up, rounding::down2(lo)), std::min(detail::pi_up, rounding::up2(hi))};
}
inline bool atan2_may_jump(Interval y, Interval x) {
    return !y.is_empty() && !x.is_empty() && y.contains(0.0) && x.lo <= 0.0;
}

namespace detail {
/// Bounds of ln(eᵃ + eᵇ) at one point, from below and from above, as
/// max(a, b) + ln(1 + e^−|a−b|) rounded outwards (glibc's log1p is within
/// 2 ulps): each takes one exp and one log1p. Where max(a, b) is NaN or
/// infinite, that is the bound (the caller makes a NaN the empty interval).
inline double log_sum_exp_below(double a, double b) {
    const double m = max(a, b);
    if (m != m || std::isinf(m)) return m;
    const double exponent = (-abs(Interval(a) - Interval(b))).lo;
    return rounding::exact_zero_down(m + std::max(0.0, rounding::down2(std::log1p(exp_below(exponent)))));
}
inline double log_sum_exp_above(double a, double b) {
    const double m = max(a, b);
    if (m != m || std::isinf(m)) return m;
    const double exponent = (-abs(Interval(a) - Interval(b))).hi;
    return rounding::exact_zero_up(m + rounding::up2(std::log1p(exp_above(exponent))));
}
}  // namespace detail

/// ln(eᵃ + eᵇ) is increasing in both operands, so its range runs from the
/// lower corner to the upper one: tight, and finite wherever a and b are —
/// where ln(exp(a) + exp(b)) written out overflows to [·, ∞] and its
/// derivative's enclosure (e^a ∇a + e^b ∇b)/(e^a + e^b) explodes.
inline Interval log_sum_exp(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const double lo = detail::log_sum_exp_below(a.lo, b.lo), hi = detail::log_sum_exp_above(a.hi, b.hi);
    return lo != lo || hi != hi ? Interval::empty() : Interval{lo, hi};
}
/// The weight 1/(1 + e^(b−a)) of a in the derivative, decreasing in b − a:
/// an enclosure within [0, 1] (all of it where b − a is ∞ − ∞).
inline Interval log_sum_exp_weight(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const Interval x = b - a;
    if (x.lo != x.lo || x.hi != x.hi) return {0.0, 1.0};
    const Interval w = 1.0 / (1.0 + exp(x));
    return {std::max(0.0, w.lo), std::min(1.0, w.hi)};
}

/// floor is exact in floating point and non-decreasing.
inline Interval floor(Interval a) {
    if (a.is_empty()) return a;
    return {std::floor(a.lo), std::floor(a.hi)};
}
inline bool floor_may_jump(Interval a) { return !a.is_empty() && std::floor(a.lo) != std::floor(a.hi); }

/// hypot: increasing in |a| and |b|, so the range runs from the smallest
/// magnitudes to the largest (scalar hypot is within 1.5 ulps).
inline Interval hypot(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const Interval ma = abs(a), mb = abs(b);
    return {std::max(0.0, rounding::down2(hypot(ma.lo, mb.lo))), rounding::up2(hypot(ma.hi, mb.hi))};
}
/// a/h over the box, within [−1, 1]; where h may be 0 (a and b both straddle
/// it) every slope of the cone at its apex is possible: [−1, 1].
inline Interval hypot_slope(Interval a, Interval h) {
    if (a.is_empty() || h.is_empty()) return Interval::empty();
    if (!(h.lo > 0.0)) return {-1.0, 1.0};
    const Interval q = a / h;
    return {std::max(-1.0, q.lo), std::min(1.0, q.hi)};
}
inline Interval hypot_curvature(Interval n, Interval h) { return n / h; }

/// See scalar.hpp.
inline Interval unbounded_derivative(Interval /*like*/) { return Interval::entire(); }

/// a^n for an integer n.
inline Interval powi(Interval a, int n) {
    if (a.is_empty()) return a;
    if (n == 0) return Interval(1.0);
    if (n == 1) return a;
    if (n == 2) return square(a);
    if (n < 0) return Interval(1.0) / powi(a, -n);
    const auto p = [n](double v) { return std::pow(v, static_cast<double>(n)); };
    if (n % 2 == 1) {
        // Odd powers keep the sign: a bound at 0 stays at 0 (else 1/a^n of a
        // one-signed a would see a divisor straddling 0 and answer ℝ).
        const double lo = rounding::down2(p(a.lo)), hi = rounding::up2(p(a.hi));
        return {a.lo >= 0.0 ? std::max(0.0, lo) : lo, a.hi <= 0.0 ? std::min(0.0, hi) : hi};
    }
    const Interval m = abs(a);
    return {std::max(0.0, rounding::down2(p(m.lo))), rounding::up2(p(m.hi))};
}

/// The value as an int when the interval is a single, moderately sized integer.
inline std::optional<int> integer_value(Interval a) {
    if (a.lo != a.hi) return std::nullopt;
    return integer_value(a.lo);
}

/// a^b. An exponent that is a single integer behaves as powi (negative bases
/// allowed); otherwise the base is clipped to a ≥ 0, like std::pow's domain.
inline Interval pow(Interval a, Interval b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    if (const auto n = integer_value(b)) return powi(a, *n);
    if (a.hi < 0.0) return Interval::empty();
    const Interval base{std::max(a.lo, 0.0), a.hi};
    if (b.lo == b.hi) {  // a constant real exponent: monotone in the base
        const double p = b.lo;
        const double at_lo = std::pow(base.lo, p), at_hi = std::pow(base.hi, p);
        if (p > 0.0) return {std::max(0.0, rounding::down2(at_lo)), rounding::up2(at_hi)};
        return {std::max(0.0, rounding::down2(at_hi)), base.lo == 0.0 ? inf : rounding::up2(at_lo)};
    }
    // General case: a^b = exp(b · log a) over the base's positive part; at 0 the
    // value is 0 (b > 0), 1 (b = 0) or ∞ (b < 0).
    Interval r = exp(b * log(base));
    if (base.lo == 0.0) r = {0.0, b.lo < 0.0 ? inf : std::max(r.hi, 1.0)};
    return r;
}

inline Interval min(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline Interval max(Interval a, Interval b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

inline bool certainly_le(Interval a, Interval b) { return a.hi <= b.lo; }
inline Interval hull(Interval a, Interval b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
inline bool is_exact_zero(Interval a) { return a.lo == 0.0 && a.hi == 0.0; }
/// The derivative of min or max where both sides are equal: every
/// subgradient, the hull of the two one-sided ones.
inline Interval tie_derivative(Interval a, Interval b) { return hull(a, b); }

}  // namespace zeroset
