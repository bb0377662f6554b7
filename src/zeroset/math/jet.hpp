// Jet<T>: the value and the first two derivatives of a function of one
// variable t, propagated by the chain rule. Evaluating f along a ray with
// x = x_o + t·x_d gives H(t), H′(t) and H″(t) (survey eqs. 13–21); with
// T = Interval and t an interval, it encloses them over a whole ray segment —
// what the interval method (Fig. 9) needs of H′ and the LG method (Fig. 11) of H″.
#pragma once

#include "zeroset/math/interval.hpp"
#include "zeroset/math/scalar.hpp"

namespace zeroset {

template <class T>
struct Jet {
    T v{};   // H
    T d1{};  // H′
    T d2{};  // H″

    constexpr Jet() = default;
    /// A constant.
    constexpr explicit Jet(double c) : v(c), d1(0.0), d2(0.0) {}
    constexpr Jet(T v_, T d1_, T d2_) : v(v_), d1(d1_), d2(d2_) {}

    /// The affine function origin + t·direction, evaluated at t.
    static Jet line(double origin, double direction, T t) {
        return {T(origin) + T(direction) * t, T(direction), T(0.0)};
    }
};

namespace detail {
/// Chain rule for g(u): value g, first derivative g1 = g′(u), second g2 = g″(u).
template <class T>
Jet<T> chain(const Jet<T>& u, T g, T g1, T g2) {
    return {g, g1 * u.d1, g2 * square(u.d1) + g1 * u.d2};
}
/// H′ and H″ where the function may jump inside the segment: no finite bound
/// holds its change, unless the arguments do not move along the ray at all.
template <class T>
Jet<T> across_jump(T value, const Jet<T>& u, const Jet<T>& w) {
    const bool still = is_exact_zero(u.d1) && is_exact_zero(u.d2) && is_exact_zero(w.d1) && is_exact_zero(w.d2);
    const T d = still ? T(0.0) : unbounded_derivative(value);
    return {value, d, d};
}
}  // namespace detail

template <class T> Jet<T> operator+(const Jet<T>& a, const Jet<T>& b) { return {a.v + b.v, a.d1 + b.d1, a.d2 + b.d2}; }
template <class T> Jet<T> operator-(const Jet<T>& a, const Jet<T>& b) { return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2}; }
template <class T> Jet<T> operator-(const Jet<T>& a) { return {-a.v, -a.d1, -a.d2}; }
template <class T> Jet<T> operator*(const Jet<T>& a, const Jet<T>& b) {
    return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + T(2.0) * a.d1 * b.d1 + a.v * b.d2};
}
template <class T> Jet<T> operator/(const Jet<T>& a, const Jet<T>& b) {
    const T q = a.v / b.v;
    const T q1 = (a.d1 - q * b.d1) / b.v;
    const T q2 = (a.d2 - T(2.0) * q1 * b.d1 - q * b.d2) / b.v;
    return {q, q1, q2};
}

template <class T> Jet<T> square(const Jet<T>& a) {
    return {square(a.v), T(2.0) * a.v * a.d1, T(2.0) * square(a.d1) + T(2.0) * a.v * a.d2};
}
template <class T> Jet<T> sqrt(const Jet<T>& a) {
    const T s = sqrt(a.v);
    const T g1 = T(0.5) / s;
    return detail::chain(a, s, g1, -g1 / (T(2.0) * a.v));
}
template <class T> Jet<T> exp(const Jet<T>& a) {
    const T e = exp(a.v);
    return detail::chain(a, e, e, e);
}
template <class T> Jet<T> log(const Jet<T>& a) {
    const T r = T(1.0) / a.v;
    return detail::chain(a, log(a.v), r, -square(r));
}
template <class T> Jet<T> sin(const Jet<T>& a) {
    const T s = sin(a.v);
    return detail::chain(a, s, cos(a.v), -s);
}
template <class T> Jet<T> cos(const Jet<T>& a) {
    const T c = cos(a.v);
    return detail::chain(a, c, -sin(a.v), -c);
}
/// tan′ = 1 + tan², tan″ = 2 tan (1 + tan²).
template <class T> Jet<T> tan(const Jet<T>& a) {
    const T t = tan(a.v);
    if (tan_may_jump(a.v)) return detail::across_jump(t, a, a);
    const T g1 = T(1.0) + square(t);
    return detail::chain(a, t, g1, T(2.0) * t * g1);
}
/// atan′ = 1/(1 + a²), atan″ = −2a/(1 + a²)².
template <class T> Jet<T> atan(const Jet<T>& a) {
    const T g1 = T(1.0) / (T(1.0) + square(a.v));
    return detail::chain(a, atan(a.v), g1, T(-2.0) * a.v * square(g1));
}
/// H = atan2(Y, X): with N = X Y′ − Y X′ and D = X² + Y², H′ = N/D and
/// H″ = (N′ − H′ D′)/D, where N′ = X Y″ − Y X″ and D′ = 2(X X′ + Y Y′).
template <class T> Jet<T> atan2(const Jet<T>& y, const Jet<T>& x) {
    const T angle = atan2(y.v, x.v);
    if (atan2_may_jump(y.v, x.v)) return detail::across_jump(angle, y, x);
    const T d = square(x.v) + square(y.v);
    const T h1 = (x.v * y.d1 - y.v * x.d1) / d;
    const T n1 = x.v * y.d2 - y.v * x.d2;
    const T d1 = T(2.0) * (x.v * x.d1 + y.v * y.d1);
    return {angle, h1, (n1 - h1 * d1) / d};
}
/// H = hypot(A, B) with slopes α = A/H, β = B/H (α² + β² = 1):
/// H′ = α A′ + β B′ and H″ = (α B′ − β A′)²/H + α A″ + β B″.
template <class T> Jet<T> hypot(const Jet<T>& a, const Jet<T>& b) {
    const T h = hypot(a.v, b.v);
    const T alpha = hypot_slope(a.v, h), beta = hypot_slope(b.v, h);
    const T turn = alpha * b.d1 - beta * a.d1;
    return {h, alpha * a.d1 + beta * b.d1, hypot_curvature(square(turn), h) + alpha * a.d2 + beta * b.d2};
}
/// H = ln(e^A + e^B) with weights α = 1/(1 + e^(B−A)), β = 1 − α:
/// H′ = α A′ + β B′ and H″ = α A″ + β B″ + α β (A′ − B′)².
template <class T> Jet<T> log_sum_exp(const Jet<T>& a, const Jet<T>& b) {
    const T alpha = log_sum_exp_weight(a.v, b.v), beta = log_sum_exp_weight(b.v, a.v);
    return {log_sum_exp(a.v, b.v), alpha * a.d1 + beta * b.d1,
            alpha * a.d2 + beta * b.d2 + alpha * beta * square(a.d1 - b.d1)};
}
template <class T> Jet<T> floor(const Jet<T>& a) {
    const T f = floor(a.v);
    if (floor_may_jump(a.v)) return detail::across_jump(f, a, a);
    return {f, T(0.0), T(0.0)};
}
template <class T> Jet<T> powi(const Jet<T>& a, int n) {
    if (n == 0) return Jet<T>(1.0);
    if (n == 1) return a;  // the general rule would give H″ = 0 · a^(−1), NaN at a = 0
    const double nd = static_cast<double>(n);
    return detail::chain(a, powi(a.v, n), T(nd) * powi(a.v, n - 1), T(nd * (nd - 1.0)) * powi(a.v, n - 2));
}
template <class T> Jet<T> pow(const Jet<T>& a, const Jet<T>& b) {
    if (is_exact_zero(b.d1) && is_exact_zero(b.d2)) {
        // An integral exponent allows negative bases; p − 1 computed in T may
        // not be integral any more (an interval is widened), so use powi.
        if (const auto n = integer_value(b.v)) {
            Jet<T> r = powi(a, *n);
            r.v = pow(a.v, b.v);  // the very value the plain evaluators compute
            return r;
        }
        const T p = b.v;
        return detail::chain(a, pow(a.v, p), p * pow(a.v, p - T(1.0)),
                             p * (p - T(1.0)) * pow(a.v, p - T(2.0)));
    }
    return exp(b * log(a));  // a^b = e^(b ln a), for a > 0
}

namespace detail {
/// H″ where the winning branch of abs/min/max may change inside the segment.
/// H′ can jump at the kink, so no finite H″ bounds its variation there — and
/// the LG method (Fig. 11) uses max|H″| as Lip H′: the answer is unbounded.
/// (A plain number always knows the winner; only NaN gets here.)
template <std::floating_point F> F second_derivative_across_kink(F a, F /*b*/) { return a; }
inline Interval second_derivative_across_kink(Interval, Interval) { return Interval::entire(); }
}  // namespace detail

/// |a|, min, max: the winning branch; where it is ambiguous over an interval,
/// the hull of both branches' H′ (H stays continuous, so that bounds its
/// variation) and an unbounded H″ (see above; the survey's §7 notes that
/// methods needing smooth derivatives must treat such CSG with care).
template <class T> Jet<T> abs(const Jet<T>& a) {
    if (certainly_le(T(0.0), a.v)) return a;
    if (certainly_le(a.v, T(0.0))) return -a;
    return {abs(a.v), hull(a.d1, -a.d1), detail::second_derivative_across_kink(a.d2, -a.d2)};
}
template <class T> Jet<T> min(const Jet<T>& a, const Jet<T>& b) {
    if (certainly_le(a.v, b.v)) return a;
    if (certainly_le(b.v, a.v)) return b;
    return {min(a.v, b.v), hull(a.d1, b.d1), detail::second_derivative_across_kink(a.d2, b.d2)};
}
template <class T> Jet<T> max(const Jet<T>& a, const Jet<T>& b) {
    if (certainly_le(b.v, a.v)) return a;
    if (certainly_le(a.v, b.v)) return b;
    return {max(a.v, b.v), hull(a.d1, b.d1), detail::second_derivative_across_kink(a.d2, b.d2)};
}

}  // namespace zeroset
