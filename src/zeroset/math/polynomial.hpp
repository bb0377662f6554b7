// Polynomial: a polynomial in the ray parameter t, as a number type of the
// evaluator. Evaluating a polynomial f with x = x_o + t·x_d (and y, z alike)
// gives the exact coefficients of F(t) = f∘r(t) — the survey's eqs. 8–11 and
// §3.3–3.4: an algebraic surface composed with a ray is a polynomial in t,
// whose roots the closed forms (degree ≤ 4) or the polynomial solvers find.
//
// Capacity is fixed — coefficients live in a std::array, so evaluation never
// allocates. max_degree = 32: the supported degree is anything up to 32, which
// covers a product of two degree-16 factors; the surfaces in use stay far
// below (torus 4, Barth sextic 6, Chmutov octic 8, affine maps keep the
// degree). A result of higher degree is never written: it becomes Overflow.
//
// Ops outside polynomial arithmetic (division by a non-constant, sqrt, abs,
// exp, log, sin, cos, tan, atan, atan2, floor, hypot, log-sum-exp, a non-integral or variable
// exponent, min, max, a negative power) give NotPolynomial when an operand depends on t. On
// constants they are ordinary arithmetic: sqrt(2) as a radius is still a
// constant. Invalid states are sticky through every later op.
//
// Exactly zero leading coefficients are trimmed, so degree() is the degree
// along this ray (a cylinder's quadratic drops to degree 1 along its axis);
// rounding noise in a leading coefficient is left to the solvers.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

#include "zeroset/math/scalar.hpp"

namespace zeroset {

class Polynomial {
public:
    static constexpr int max_degree = 32;
    static constexpr int max_terms = max_degree + 1;

    enum class State : std::uint8_t {
        Valid,
        Overflow,       // the degree would exceed max_degree
        NotPolynomial,  // a non-polynomial op on a t-dependent operand
    };

    /// The zero polynomial.
    constexpr Polynomial() = default;
    /// A constant.
    constexpr explicit Polynomial(double c) { c_[0] = c; }

    /// origin + direction·t.
    static constexpr Polynomial line(double origin, double direction) {
        Polynomial p(origin);
        p.c_[1] = direction;
        p.degree_ = 1;
        p.trim();
        return p;
    }

    /// From ascending coefficients c₀, c₁, …; more than max_terms overflow.
    static constexpr Polynomial from_coefficients(std::span<const double> c) {
        if (c.size() > max_terms) return invalid(State::Overflow);
        Polynomial p;
        std::copy(c.begin(), c.end(), p.c_.begin());
        p.degree_ = c.empty() ? 0 : static_cast<int>(c.size()) - 1;
        p.trim();
        return p;
    }

    static constexpr Polynomial invalid(State s) {
        Polynomial p;
        p.state_ = s;
        return p;
    }

    [[nodiscard]] constexpr State state() const { return state_; }
    [[nodiscard]] constexpr bool valid() const { return state_ == State::Valid; }
    [[nodiscard]] constexpr int degree() const { return degree_; }
    [[nodiscard]] constexpr bool is_constant() const { return valid() && degree_ == 0; }
    /// The coefficient of tⁱ (0 beyond the degree).
    [[nodiscard]] constexpr double operator[](int i) const { return i >= 0 && i <= degree_ ? c_[i] : 0.0; }
    /// c₀ … c_degree, ascending.
    [[nodiscard]] std::span<const double> coefficients() const {
        return {c_.data(), static_cast<std::size_t>(degree_) + 1};
    }

    /// F(t) by Horner's rule.
    [[nodiscard]] constexpr double operator()(double t) const {
        double r = c_[degree_];
        for (int i = degree_ - 1; i >= 0; --i) r = r * t + c_[i];
        return r;
    }

    [[nodiscard]] constexpr Polynomial derivative() const {
        if (!valid()) return *this;
        Polynomial d;
        for (int i = 1; i <= degree_; ++i) d.c_[i - 1] = static_cast<double>(i) * c_[i];
        d.degree_ = std::max(0, degree_ - 1);
        d.trim();
        return d;
    }

    /// Ascending, e.g. "36.852421 - 12.1476884 t + 1.00024084 t^2", shortest
    /// round-trip digits; "overflow" or "not a polynomial" when invalid.
    [[nodiscard]] std::string to_string() const {
        if (state_ == State::Overflow) return "overflow";
        if (state_ == State::NotPolynomial) return "not a polynomial";
        std::string s;
        for (int i = 0; i <= degree_; ++i) {
            const double c = c_[i];
            if (c == 0.0 && degree_ > 0) continue;
            if (!s.empty()) s += std::signbit(c) ? " - " : " + ";
            std::array<char, 32> buf{};
            const double shown = s.empty() ? c : std::fabs(c);
            const auto end = std::to_chars(buf.data(), buf.data() + buf.size(), shown).ptr;
            s.append(buf.data(), end);
            if (i >= 1) s += " t";
            if (i >= 2) s += "^" + std::to_string(i);
        }
        return s;
    }

    friend constexpr Polynomial operator+(const Polynomial& a, const Polynomial& b) {
        return combine(a, b, 1.0);
    }
    friend constexpr Polynomial operator-(const Polynomial& a, const Polynomial& b) {
        return combine(a, b, -1.0);
    }
    friend constexpr Polynomial operator-(const Polynomial& a) {
        Polynomial r = a;
        for (int i = 0; i <= r.degree_; ++i) r.c_[i] = -r.c_[i];
        return r;
    }
    friend constexpr Polynomial operator*(const Polynomial& a, const Polynomial& b) {
        if (!a.valid() || !b.valid()) return worse(a, b);
        if (a.degree_ + b.degree_ > max_degree) return invalid(State::Overflow);
        Polynomial r;
        r.degree_ = a.degree_ + b.degree_;
        for (int i = 0; i <= a.degree_; ++i)
            for (int j = 0; j <= b.degree_; ++j) r.c_[i + j] += a.c_[i] * b.c_[j];
        r.trim();
        return r;
    }
    /// Division by a nonzero constant only.
    friend constexpr Polynomial operator/(const Polynomial& a, const Polynomial& b) {
        if (!a.valid() || !b.valid()) return worse(a, b);
        if (a.degree_ == 0 && b.degree_ == 0) return Polynomial(a.c_[0] / b.c_[0]);
        if (b.degree_ != 0 || b.c_[0] == 0.0) return invalid(State::NotPolynomial);
        Polynomial r = a;
        for (int i = 0; i <= r.degree_; ++i) r.c_[i] /= b.c_[0];
        return r;
    }

private:
    static constexpr Polynomial worse(const Polynomial& a, const Polynomial& b) {
        return invalid(std::max(a.state_, b.state_));
    }
    static constexpr Polynomial combine(const Polynomial& a, const Polynomial& b, double sign) {
        if (!a.valid() || !b.valid()) return worse(a, b);
        Polynomial r = a;
        r.degree_ = std::max(a.degree_, b.degree_);
        for (int i = 0; i <= b.degree_; ++i) r.c_[i] += sign * b.c_[i];
        r.trim();
        return r;
    }
    constexpr void trim() {
        while (degree_ > 0 && c_[degree_] == 0.0) --degree_;
    }

    std::array<double, max_terms> c_{};
    int degree_ = 0;
    State state_ = State::Valid;
};

inline Polynomial square(const Polynomial& a) { return a * a; }

/// aⁿ by repeated squaring; n < 0 is polynomial only for a constant.
inline Polynomial powi(const Polynomial& a, int n) {
    if (!a.valid()) return a;
    if (a.degree() == 0) return Polynomial(powi(a[0], n));
    if (n < 0) return Polynomial::invalid(Polynomial::State::NotPolynomial);
    if (a.degree() > Polynomial::max_degree / std::max(n, 1)) return Polynomial::invalid(Polynomial::State::Overflow);
    Polynomial result(1.0);
    Polynomial base = a;
    while (n != 0) {
        if (n & 1) result = result * base;
        n >>= 1;
        if (n != 0) base = base * base;
    }
    return result;
}

namespace detail {
/// g applied to a constant; NotPolynomial for anything depending on t.
template <class G>
Polynomial on_constant(const Polynomial& a, G g) {
    if (!a.valid()) return a;
    if (a.degree() != 0) return Polynomial::invalid(Polynomial::State::NotPolynomial);
    return Polynomial(g(a[0]));
}
template <class G>
Polynomial on_constants(const Polynomial& a, const Polynomial& b, G g) {
    if (!a.valid()) return a;
    if (!b.valid()) return b;
    if (a.degree() != 0 || b.degree() != 0) return Polynomial::invalid(Polynomial::State::NotPolynomial);
    return Polynomial(g(a[0], b[0]));
}
}  // namespace detail

inline Polynomial sqrt(const Polynomial& a) { return detail::on_constant(a, [](double v) { return sqrt(v); }); }
inline Polynomial abs(const Polynomial& a) { return detail::on_constant(a, [](double v) { return abs(v); }); }
inline Polynomial exp(const Polynomial& a) { return detail::on_constant(a, [](double v) { return exp(v); }); }
inline Polynomial log(const Polynomial& a) { return detail::on_constant(a, [](double v) { return log(v); }); }
inline Polynomial sin(const Polynomial& a) { return detail::on_constant(a, [](double v) { return sin(v); }); }
inline Polynomial cos(const Polynomial& a) { return detail::on_constant(a, [](double v) { return cos(v); }); }
inline Polynomial tan(const Polynomial& a) { return detail::on_constant(a, [](double v) { return tan(v); }); }
inline Polynomial atan(const Polynomial& a) { return detail::on_constant(a, [](double v) { return atan(v); }); }
inline Polynomial floor(const Polynomial& a) { return detail::on_constant(a, [](double v) { return floor(v); }); }
inline Polynomial hypot(const Polynomial& a, const Polynomial& b) {
    return detail::on_constants(a, b, [](double u, double v) { return hypot(u, v); });
}
inline Polynomial log_sum_exp(const Polynomial& a, const Polynomial& b) {
    return detail::on_constants(a, b, [](double u, double v) { return log_sum_exp(u, v); });
}
inline Polynomial atan2(const Polynomial& y, const Polynomial& x) {
    return detail::on_constants(y, x, [](double u, double v) { return atan2(u, v); });
}
inline Polynomial min(const Polynomial& a, const Polynomial& b) {
    return detail::on_constants(a, b, [](double u, double v) { return min(u, v); });
}
inline Polynomial max(const Polynomial& a, const Polynomial& b) {
    return detail::on_constants(a, b, [](double u, double v) { return max(u, v); });
}

/// aᵇ: a constant integral exponent is powi; otherwise only constants.
inline Polynomial pow(const Polynomial& a, const Polynomial& b) {
    if (!a.valid()) return a;
    if (!b.valid()) return b;
    if (b.degree() == 0) {
        if (const auto n = integer_value(b[0])) return powi(a, *n);
    }
    return detail::on_constants(a, b, [](double u, double v) { return pow(u, v); });
}

}  // namespace zeroset
