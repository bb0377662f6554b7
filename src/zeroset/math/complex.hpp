// Complex: a complex number as one more number type of the evaluator, so the
// tape can be walked at a complex ray parameter t. The survey's Figure 5 maps,
// for every start t₀ in the complex plane, the root Newton's method (eq. 22)
// converges to; that needs H(t) and H′(t) at complex t — Evaluator<Complex>
// and Evaluator<Jet<Complex>> (render/newton_basins.hpp).
//
// Every analytic op is its principal-branch continuation: sqrt, log and pow
// (non-integral exponent) are cut along the negative real axis, tan has its
// poles at π/2 + kπ and atan its cuts on the imaginary axis beyond ±i, as in
// std::complex. atan2 is continued as the angle of x + iy,
//   atan2(y, x) = −i log((x + iy) / √(x² + y²)),
// which is the real atan2 for real x, y (cut where x + iy is a negative real)
// and has the real rule's derivatives (x dy − y dx)/(x² + y²); hypot(a, b)
// is √(a² + b²). abs, min, max
// and floor have no analytic continuation; they pick a branch by real parts,
// which agrees with the real functions on the real axis and is analytic away
// from the switching lines:
//   abs(z)    = z if Re z ≥ 0, else −z   (√(z²) on the principal branch,
//                                        with z itself on the imaginary axis)
//   min(a, b) = a if Re a ≤ Re b, else b   (max likewise)
//   floor(z)  = ⌊Re z⌋, a real constant on each strip k ≤ Re z < k + 1
// A NaN operand of min/max propagates, as for plain numbers.
#pragma once

#include <cmath>
#include <complex>
#include <limits>
#include <optional>

#include "zeroset/math/jet.hpp"
#include "zeroset/math/scalar.hpp"

namespace zeroset {

struct Complex {
    double re = 0.0;
    double im = 0.0;

    constexpr Complex() = default;
    /// A real number.
    constexpr explicit Complex(double r) : re(r) {}
    constexpr Complex(double r, double i) : re(r), im(i) {}

    friend constexpr bool operator==(const Complex&, const Complex&) = default;
};

namespace detail {
inline std::complex<double> to_std(Complex a) { return {a.re, a.im}; }
inline Complex from_std(std::complex<double> a) { return {a.real(), a.imag()}; }
inline bool has_nan(Complex a) { return std::isnan(a.re) || std::isnan(a.im); }
}  // namespace detail

inline constexpr Complex operator+(Complex a, Complex b) { return {a.re + b.re, a.im + b.im}; }
inline constexpr Complex operator-(Complex a, Complex b) { return {a.re - b.re, a.im - b.im}; }
inline constexpr Complex operator-(Complex a) { return {-a.re, -a.im}; }
inline constexpr Complex operator*(Complex a, Complex b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
/// Division as std::complex does it (scaled, so |b| near the overflow or
/// underflow threshold does not spoil the quotient).
inline Complex operator/(Complex a, Complex b) { return detail::from_std(detail::to_std(a) / detail::to_std(b)); }

/// |a|, the modulus (not abs: that is the continuation of the real |x|).
inline double modulus(Complex a) { return std::hypot(a.re, a.im); }
inline bool is_finite(Complex a) { return std::isfinite(a.re) && std::isfinite(a.im); }

inline constexpr Complex square(Complex a) { return a * a; }
inline Complex sqrt(Complex a) { return detail::from_std(std::sqrt(detail::to_std(a))); }
inline Complex exp(Complex a) { return detail::from_std(std::exp(detail::to_std(a))); }
inline Complex log(Complex a) { return detail::from_std(std::log(detail::to_std(a))); }
inline Complex sin(Complex a) { return detail::from_std(std::sin(detail::to_std(a))); }
inline Complex cos(Complex a) { return detail::from_std(std::cos(detail::to_std(a))); }
inline Complex tan(Complex a) { return detail::from_std(std::tan(detail::to_std(a))); }
inline Complex atan(Complex a) { return detail::from_std(std::atan(detail::to_std(a))); }
inline Complex atan2(Complex y, Complex x) {
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> w = detail::to_std(x) + i * detail::to_std(y);
    const std::complex<double> r = std::sqrt(detail::to_std(square(x) + square(y)));
    return detail::from_std(-i * std::log(w / r));
}
inline Complex floor(Complex a) { return Complex(std::floor(a.re)); }
/// √(a² + b²) on the principal branch (the real hypot on the real axis).
inline Complex hypot(Complex a, Complex b) { return sqrt(square(a) + square(b)); }
inline Complex hypot_slope(Complex a, Complex h) { return a / h; }
inline Complex hypot_curvature(Complex n, Complex h) { return n / h; }

/// log(eᵃ + eᵇ) on the principal branch, with both exponents shifted by the
/// larger real part m (e^−m is real and positive, so the branch is unchanged).
inline Complex log_sum_exp(Complex a, Complex b) {
    const Complex m(std::max(a.re, b.re));
    if (!std::isfinite(m.re)) return log(exp(a) + exp(b));
    return m + log(exp(a - m) + exp(b - m));
}
inline Complex log_sum_exp_weight(Complex a, Complex b) { return Complex(1.0) / (Complex(1.0) + exp(b - a)); }

/// a^n by repeated squaring: exact branch-free integer powers.
inline Complex powi(Complex a, int n) {
    if (n < 0) return Complex(1.0) / powi(a, -n);
    Complex result(1.0);
    for (Complex base = a; n != 0; n >>= 1) {
        if (n & 1) result = result * base;
        base = square(base);
    }
    return result;
}

/// The value as an int when it is real and exactly a moderate integer.
inline std::optional<int> integer_value(Complex a) {
    if (a.im != 0.0) return std::nullopt;
    return integer_value(a.re);
}
inline bool is_exact_zero(Complex a) { return a.re == 0.0 && a.im == 0.0; }
// A complex number is one point: like a double, it never straddles a jump
// (see scalar.hpp), so Jet<Complex> takes the one-sided derivatives.
inline bool floor_may_jump(Complex) { return false; }
inline bool tan_may_jump(Complex) { return false; }
inline bool atan2_may_jump(Complex, Complex) { return false; }
inline Complex unbounded_derivative(Complex) { return Complex(std::numeric_limits<double>::infinity()); }

/// a^b on the principal branch, e^(b·log a); an integral b is powi (so a
/// negative base is fine, as for plain numbers), and a real b on a
/// non-negative real a is the real pow (so 0^b is 0, ∞ or 1 as there).
inline Complex pow(Complex a, Complex b) {
    if (const auto n = integer_value(b)) return powi(a, *n);
    if (a.im == 0.0 && b.im == 0.0 && a.re >= 0.0) return Complex(std::pow(a.re, b.re));
    return exp(b * log(a));
}

inline Complex abs(Complex a) { return a.re >= 0.0 ? a : -a; }
inline Complex min(Complex a, Complex b) {
    if (detail::has_nan(a) || detail::has_nan(b)) return a + b;
    return a.re <= b.re ? a : b;
}
inline Complex max(Complex a, Complex b) {
    if (detail::has_nan(a) || detail::has_nan(b)) return a + b;
    return a.re >= b.re ? a : b;
}

// Jet<Complex>: the generic rules of jet.hpp serve every analytic op. abs,
// min and max take the branch their Complex versions take, with its
// derivatives (the generic ones would ask whether the branch is ambiguous,
// which a real-part rule never is).
inline Jet<Complex> abs(const Jet<Complex>& a) { return a.v.re >= 0.0 ? a : -a; }
inline Jet<Complex> min(const Jet<Complex>& a, const Jet<Complex>& b) {
    if (detail::has_nan(a.v) || detail::has_nan(b.v)) return a + b;
    return a.v.re <= b.v.re ? a : b;
}
inline Jet<Complex> max(const Jet<Complex>& a, const Jet<Complex>& b) {
    if (detail::has_nan(a.v) || detail::has_nan(b.v)) return a + b;
    return a.v.re >= b.v.re ? a : b;
}

}  // namespace zeroset
