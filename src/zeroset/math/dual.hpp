// Dual<T>: a value and its gradient ∇f = (∂f/∂x, ∂f/∂y, ∂f/∂z), carried
// through every operation by the chain rule (forward-mode differentiation).
// Dual<double> gives exact normals (survey eq. 33); Dual<Interval> encloses
// the gradient over a box, which bounds the Lipschitz constant (eq. 30).
// With one T for its gradient (DirectionalDual) it carries the derivative
// along a single direction instead — H′ of H(t) = f(x_o + t·x_d) when the
// variables are seeded with x_d's components — at a third of the cost.
#pragma once

#include <type_traits>

#include "zeroset/math/interval.hpp"
#include "zeroset/math/scalar.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

template <class T, class G = Vec3<T>>
struct Dual {
    T v{};
    G g{};  // the gradient, or the derivative along one direction

    constexpr Dual() = default;
    /// A constant: zero gradient.
    constexpr explicit Dual(double c) : v(c), g() {}
    constexpr Dual(T v_, G g_) : v(v_), g(g_) {}

    /// The coordinate variable number `axis` (0 = x, 1 = y, 2 = z) with value v.
    static Dual variable(T value, int axis)
        requires std::is_same_v<G, Vec3<T>>
    {
        Dual d{value, {T(0.0), T(0.0), T(0.0)}};
        d.g[axis] = T(1.0);
        return d;
    }
};

/// f and its derivative along one direction.
template <class T>
using DirectionalDual = Dual<T, T>;

namespace detail {
/// f applied to a gradient's components pairwise: a Vec3's three, or the one of a directional derivative.
template <class T, class F>
T zip(const T& a, const T& b, F f) {
    return f(a, b);
}
template <class T, class F>
Vec3<T> zip(const Vec3<T>& a, const Vec3<T>& b, F f) {
    return {f(a.x, b.x), f(a.y, b.y), f(a.z, b.z)};
}
template <class T>
bool all_exact_zero(const T& a) {
    return is_exact_zero(a);
}
template <class T>
bool all_exact_zero(const Vec3<T>& a) {
    return is_exact_zero(a.x) && is_exact_zero(a.y) && is_exact_zero(a.z);
}
/// The chain rule for a unary function with derivative `dg` at the argument.
template <class T, class G>
Dual<T, G> chain(const Dual<T, G>& u, T value, T dg) {
    return {value, u.g * dg};
}
/// A function that may jump inside the argument(s): each component of the
/// gradient is 0 where no argument moves along that axis, else unbounded.
template <class T, class G>
Dual<T, G> across_jump(T value, const G& g, const G& h) {
    return {value, zip(g, h, [](const T& a, const T& b) {
                return is_exact_zero(a) && is_exact_zero(b) ? T(0.0) : unbounded_derivative(a);
            })};
}
}  // namespace detail

template <class T, class G> Dual<T, G> operator+(const Dual<T, G>& a, const Dual<T, G>& b) { return {a.v + b.v, a.g + b.g}; }
template <class T, class G> Dual<T, G> operator-(const Dual<T, G>& a, const Dual<T, G>& b) { return {a.v - b.v, a.g - b.g}; }
template <class T, class G> Dual<T, G> operator-(const Dual<T, G>& a) { return {-a.v, -a.g}; }
template <class T, class G> Dual<T, G> operator*(const Dual<T, G>& a, const Dual<T, G>& b) { return {a.v * b.v, a.g * b.v + b.g * a.v}; }
template <class T, class G> Dual<T, G> operator/(const Dual<T, G>& a, const Dual<T, G>& b) {
    const T q = a.v / b.v;
    return {q, (a.g - b.g * q) / b.v};
}

template <class T, class G> Dual<T, G> square(const Dual<T, G>& a) { return detail::chain(a, square(a.v), T(2.0) * a.v); }
template <class T, class G> Dual<T, G> sqrt(const Dual<T, G>& a) {
    const T s = sqrt(a.v);
    return detail::chain(a, s, T(0.5) / s);
}
template <class T, class G> Dual<T, G> exp(const Dual<T, G>& a) {
    const T e = exp(a.v);
    return detail::chain(a, e, e);
}
template <class T, class G> Dual<T, G> log(const Dual<T, G>& a) { return detail::chain(a, log(a.v), T(1.0) / a.v); }
template <class T, class G> Dual<T, G> sin(const Dual<T, G>& a) { return detail::chain(a, sin(a.v), cos(a.v)); }
template <class T, class G> Dual<T, G> cos(const Dual<T, G>& a) { return detail::chain(a, cos(a.v), -sin(a.v)); }
template <class T, class G> Dual<T, G> tan(const Dual<T, G>& a) {
    const T t = tan(a.v);
    if (tan_may_jump(a.v)) return detail::across_jump<T, G>(t, a.g, a.g);
    return detail::chain(a, t, T(1.0) + square(t));
}
template <class T, class G> Dual<T, G> atan(const Dual<T, G>& a) {
    return detail::chain(a, atan(a.v), T(1.0) / (T(1.0) + square(a.v)));
}
/// ∇atan2(y, x) = (x ∇y − y ∇x) / (x² + y²); unbounded across the cut.
template <class T, class G> Dual<T, G> atan2(const Dual<T, G>& y, const Dual<T, G>& x) {
    const T angle = atan2(y.v, x.v);
    if (atan2_may_jump(y.v, x.v)) return detail::across_jump<T, G>(angle, y.g, x.g);
    const T r = T(1.0) / (square(x.v) + square(y.v));
    return {angle, (y.g * x.v - x.g * y.v) * r};
}
/// ∇hypot(a, b) = (a ∇a + b ∇b)/h, with the slopes a/h, b/h enclosed in
/// [−1, 1] even where h may be 0: a norm stays 1-Lipschitz.
template <class T, class G> Dual<T, G> hypot(const Dual<T, G>& a, const Dual<T, G>& b) {
    const T h = hypot(a.v, b.v);
    return {h, a.g * hypot_slope(a.v, h) + b.g * hypot_slope(b.v, h)};
}
/// ∇ln(eᵃ + eᵇ) = wₐ ∇a + w_b ∇b with the weights wₐ = 1/(1 + e^(b−a)) and
/// w_b = 1 − wₐ, each enclosed in [0, 1].
template <class T, class G> Dual<T, G> log_sum_exp(const Dual<T, G>& a, const Dual<T, G>& b) {
    return {log_sum_exp(a.v, b.v), a.g * log_sum_exp_weight(a.v, b.v) + b.g * log_sum_exp_weight(b.v, a.v)};
}
/// floor′ = 0 between the integers; unbounded where an integer may be crossed.
template <class T, class G> Dual<T, G> floor(const Dual<T, G>& a) {
    const T f = floor(a.v);
    if (floor_may_jump(a.v)) return detail::across_jump<T, G>(f, a.g, a.g);
    return {f, G()};
}
template <class T, class G> Dual<T, G> powi(const Dual<T, G>& a, int n) {
    if (n == 0) return Dual<T, G>(1.0);
    return detail::chain(a, powi(a.v, n), T(static_cast<double>(n)) * powi(a.v, n - 1));
}
template <class T, class G> Dual<T, G> pow(const Dual<T, G>& a, const Dual<T, G>& b) {
    const bool constant_exponent = detail::all_exact_zero(b.g);
    if (constant_exponent) {
        // An integral exponent allows negative bases; b − 1 computed in T may
        // not be integral any more (an interval is widened), so use powi.
        if (const auto n = integer_value(b.v)) {
            Dual<T, G> r = powi(a, *n);
            r.v = pow(a.v, b.v);  // the very value the plain evaluators compute
            return r;
        }
        return detail::chain(a, pow(a.v, b.v), b.v * pow(a.v, b.v - T(1.0)));
    }
    return exp(b * log(a));  // a^b = e^(b ln a), for a > 0
}

/// |a|: the sign picks the branch; where the sign is unknown (an interval
/// around 0) the gradient is the hull of both branches.
template <class T, class G> Dual<T, G> abs(const Dual<T, G>& a) {
    if (certainly_le(T(0.0), a.v)) return a;
    if (certainly_le(a.v, T(0.0))) return -a;
    return {abs(a.v), detail::zip(a.g, a.g, [](const T& d, const T&) { return hull(d, -d); })};
}
/// min/max take the gradient of the side that wins; where either side can win
/// over an interval, the hull of both (a sound enclosure of the subgradient);
/// where the sides are exactly equal, their tie_derivative.
template <class T, class G> Dual<T, G> min(const Dual<T, G>& a, const Dual<T, G>& b) {
    const bool a_wins = certainly_le(a.v, b.v), b_wins = certainly_le(b.v, a.v);
    if (a_wins && b_wins) return {a.v, detail::zip(a.g, b.g, [](const T& p, const T& q) { return tie_derivative(p, q); })};
    if (a_wins) return a;
    if (b_wins) return b;
    return {min(a.v, b.v), detail::zip(a.g, b.g, [](const T& p, const T& q) { return hull(p, q); })};
}
template <class T, class G> Dual<T, G> max(const Dual<T, G>& a, const Dual<T, G>& b) {
    const bool a_wins = certainly_le(b.v, a.v), b_wins = certainly_le(a.v, b.v);
    if (a_wins && b_wins) return {a.v, detail::zip(a.g, b.g, [](const T& p, const T& q) { return tie_derivative(p, q); })};
    if (a_wins) return a;
    if (b_wins) return b;
    return {max(a.v, b.v), detail::zip(a.g, b.g, [](const T& p, const T& q) { return hull(p, q); })};
}

}  // namespace zeroset
