// Dual<T>: a value and its gradient ∇f = (∂f/∂x, ∂f/∂y, ∂f/∂z), carried
// through every operation by the chain rule (forward-mode differentiation).
// Dual<double> gives exact normals (survey eq. 33); Dual<Interval> encloses
// the gradient over a box, which bounds the Lipschitz constant (eq. 30).
#pragma once

#include "zeroset/math/interval.hpp"
#include "zeroset/math/scalar.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

template <class T>
struct Dual {
    T v{};
    Vec3<T> g{};  // gradient

    constexpr Dual() = default;
    /// A constant: zero gradient.
    constexpr explicit Dual(double c) : v(c), g(T(0.0), T(0.0), T(0.0)) {}
    constexpr Dual(T v_, Vec3<T> g_) : v(v_), g(g_) {}

    /// The coordinate variable number `axis` (0 = x, 1 = y, 2 = z) with value v.
    static Dual variable(T value, int axis) {
        Dual d{value, {T(0.0), T(0.0), T(0.0)}};
        d.g[axis] = T(1.0);
        return d;
    }
};

namespace detail {
template <class T>
Vec3<T> tie_gradient(const Vec3<T>& a, const Vec3<T>& b) {
    return {tie_derivative(a.x, b.x), tie_derivative(a.y, b.y), tie_derivative(a.z, b.z)};
}
/// The chain rule for a unary function with derivative `dg` at the argument.
template <class T>
Dual<T> chain(const Dual<T>& u, T value, T dg) {
    return {value, u.g * dg};
}
/// A function that may jump inside the argument(s): each component of the
/// gradient is 0 where no argument moves along that axis, else unbounded.
template <class T>
Dual<T> across_jump(T value, const Vec3<T>& g, const Vec3<T>& h) {
    Vec3<T> r;
    for (int i = 0; i < 3; ++i) r[i] = is_exact_zero(g[i]) && is_exact_zero(h[i]) ? T(0.0) : unbounded_derivative(g[i]);
    return {value, r};
}
}  // namespace detail

template <class T> Dual<T> operator+(const Dual<T>& a, const Dual<T>& b) { return {a.v + b.v, a.g + b.g}; }
template <class T> Dual<T> operator-(const Dual<T>& a, const Dual<T>& b) { return {a.v - b.v, a.g - b.g}; }
template <class T> Dual<T> operator-(const Dual<T>& a) { return {-a.v, -a.g}; }
template <class T> Dual<T> operator*(const Dual<T>& a, const Dual<T>& b) { return {a.v * b.v, a.g * b.v + b.g * a.v}; }
template <class T> Dual<T> operator/(const Dual<T>& a, const Dual<T>& b) {
    const T q = a.v / b.v;
    return {q, (a.g - b.g * q) / b.v};
}

template <class T> Dual<T> square(const Dual<T>& a) { return detail::chain(a, square(a.v), T(2.0) * a.v); }
template <class T> Dual<T> sqrt(const Dual<T>& a) {
    const T s = sqrt(a.v);
    return detail::chain(a, s, T(0.5) / s);
}
template <class T> Dual<T> exp(const Dual<T>& a) {
    const T e = exp(a.v);
    return detail::chain(a, e, e);
}
template <class T> Dual<T> log(const Dual<T>& a) { return detail::chain(a, log(a.v), T(1.0) / a.v); }
template <class T> Dual<T> sin(const Dual<T>& a) { return detail::chain(a, sin(a.v), cos(a.v)); }
template <class T> Dual<T> cos(const Dual<T>& a) { return detail::chain(a, cos(a.v), -sin(a.v)); }
template <class T> Dual<T> tan(const Dual<T>& a) {
    const T t = tan(a.v);
    if (tan_may_jump(a.v)) return detail::across_jump(t, a.g, a.g);
    return detail::chain(a, t, T(1.0) + square(t));
}
template <class T> Dual<T> atan(const Dual<T>& a) {
    return detail::chain(a, atan(a.v), T(1.0) / (T(1.0) + square(a.v)));
}
/// ∇atan2(y, x) = (x ∇y − y ∇x) / (x² + y²); unbounded across the cut.
template <class T> Dual<T> atan2(const Dual<T>& y, const Dual<T>& x) {
    const T angle = atan2(y.v, x.v);
    if (atan2_may_jump(y.v, x.v)) return detail::across_jump(angle, y.g, x.g);
    const T r = T(1.0) / (square(x.v) + square(y.v));
    return {angle, (y.g * x.v - x.g * y.v) * r};
}
/// ∇hypot(a, b) = (a ∇a + b ∇b)/h, with the slopes a/h, b/h enclosed in
/// [−1, 1] even where h may be 0: a norm stays 1-Lipschitz.
template <class T> Dual<T> hypot(const Dual<T>& a, const Dual<T>& b) {
    const T h = hypot(a.v, b.v);
    return {h, a.g * hypot_slope(a.v, h) + b.g * hypot_slope(b.v, h)};
}
/// ∇ln(eᵃ + eᵇ) = wₐ ∇a + w_b ∇b with the weights wₐ = 1/(1 + e^(b−a)) and
/// w_b = 1 − wₐ, each enclosed in [0, 1].
template <class T> Dual<T> log_sum_exp(const Dual<T>& a, const Dual<T>& b) {
    return {log_sum_exp(a.v, b.v), a.g * log_sum_exp_weight(a.v, b.v) + b.g * log_sum_exp_weight(b.v, a.v)};
}
/// floor′ = 0 between the integers; unbounded where an integer may be crossed.
template <class T> Dual<T> floor(const Dual<T>& a) {
    const T f = floor(a.v);
    if (floor_may_jump(a.v)) return detail::across_jump(f, a.g, a.g);
    return {f, {T(0.0), T(0.0), T(0.0)}};
}
template <class T> Dual<T> powi(const Dual<T>& a, int n) {
    if (n == 0) return Dual<T>(1.0);
    return detail::chain(a, powi(a.v, n), T(static_cast<double>(n)) * powi(a.v, n - 1));
}
template <class T> Dual<T> pow(const Dual<T>& a, const Dual<T>& b) {
    const bool constant_exponent = is_exact_zero(b.g.x) && is_exact_zero(b.g.y) && is_exact_zero(b.g.z);
    if (constant_exponent) {
        // An integral exponent allows negative bases; b − 1 computed in T may
        // not be integral any more (an interval is widened), so use powi.
        if (const auto n = integer_value(b.v)) {
            Dual<T> r = powi(a, *n);
            r.v = pow(a.v, b.v);  // the very value the plain evaluators compute
            return r;
        }
        return detail::chain(a, pow(a.v, b.v), b.v * pow(a.v, b.v - T(1.0)));
    }
    return exp(b * log(a));  // a^b = e^(b ln a), for a > 0
}

/// |a|: the sign picks the branch; where the sign is unknown (an interval
/// around 0) the gradient is the hull of both branches.
template <class T> Dual<T> abs(const Dual<T>& a) {
    if (certainly_le(T(0.0), a.v)) return a;
    if (certainly_le(a.v, T(0.0))) return -a;
    return {abs(a.v), {hull(a.g.x, -a.g.x), hull(a.g.y, -a.g.y), hull(a.g.z, -a.g.z)}};
}
/// min/max take the gradient of the side that wins; where either side can win
/// over an interval, the hull of both (a sound enclosure of the subgradient);
/// where the sides are exactly equal, their tie_derivative.
template <class T> Dual<T> min(const Dual<T>& a, const Dual<T>& b) {
    const bool a_wins = certainly_le(a.v, b.v), b_wins = certainly_le(b.v, a.v);
    if (a_wins && b_wins) return {a.v, detail::tie_gradient(a.g, b.g)};
    if (a_wins) return a;
    if (b_wins) return b;
    return {min(a.v, b.v), {hull(a.g.x, b.g.x), hull(a.g.y, b.g.y), hull(a.g.z, b.g.z)}};
}
template <class T> Dual<T> max(const Dual<T>& a, const Dual<T>& b) {
    const bool a_wins = certainly_le(b.v, a.v), b_wins = certainly_le(a.v, b.v);
    if (a_wins && b_wins) return {a.v, detail::tie_gradient(a.g, b.g)};
    if (a_wins) return a;
    if (b_wins) return b;
    return {max(a.v, b.v), {hull(a.g.x, b.g.x), hull(a.g.y, b.g.y), hull(a.g.z, b.g.z)}};
}

}  // namespace zeroset
