// What the polynomial root solvers share (survey §3.4: an algebraic surface
// along a ray is a polynomial F(t)). The polynomial is given by its
// coefficients in ascending powers, c[0] + c[1]·t + … + c[n]·tⁿ, with degree
// n ≤ max_polynomial_degree so that every solver works in fixed-size scratch
// arrays and allocates nothing. The roots wanted are the real ones in
// [t0, t1], in increasing order, written into a caller's buffer; a buffer of
// one element asks for the first root (the first hit along the ray), and the
// solvers that work from left to right stop there.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>

#include "zeroset/roots/root_function.hpp"

namespace zeroset {

inline constexpr int max_polynomial_degree = 32;
using PolynomialScratch = std::array<double, max_polynomial_degree + 1>;

struct PolynomialRoots {
    /// Roots written to the output buffer (at most its size).
    int count = 0;
    /// Work in units of one polynomial evaluation: one per Horner pass (value
    /// and derivative together, or value and error bound), per member of a
    /// Sturm sequence evaluated, per conversion to the Bernstein basis or de
    /// Casteljau subdivision, per closed-form quadratic, per Laguerre step.
    int evaluations = 0;
};

struct FirstPolynomialRoot {
    bool found = false;
    double t = std::numeric_limits<double>::quiet_NaN();
    int evaluations = 0;
};

/// The degree of c once zero leading (highest-power) coefficients are dropped;
/// −1 for the zero polynomial. Throws std::invalid_argument when that degree
/// exceeds max_polynomial_degree, or unless t0 ≤ t1 are finite.
inline int checked_degree(std::span<const double> c, double t0, double t1) {
    if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0) {
        throw std::invalid_argument("polynomial roots need finite t0 <= t1");
    }
    int n = static_cast<int>(c.size()) - 1;
    while (n >= 0 && c[static_cast<std::size_t>(n)] == 0.0) --n;
    if (n > max_polynomial_degree) throw std::invalid_argument("polynomial degree above 32");
    return n;
}

/// p(t) and p′(t) in one Horner pass.
[[nodiscard]] inline ValueAndDerivative horner(std::span<const double> c, double t) {
    double value = 0.0;
    double derivative = 0.0;
    for (std::size_t i = c.size(); i-- > 0;) {
        derivative = derivative * t + value;
        value = value * t + c[i];
    }
    return {value, derivative};
}

/// A bound on the rounding error of horner(c, t).value: γ₂ₙ·Σ|cᵢ||t|ⁱ
/// (Higham, Accuracy and Stability of Numerical Algorithms, §5.1).
[[nodiscard]] inline double horner_error_bound(std::span<const double> c, double t) {
    double sum = 0.0;
    const double x = std::abs(t);
    for (std::size_t i = c.size(); i-- > 0;) sum = sum * x + std::abs(c[i]);
    const double n2u = 2.0 * static_cast<double>(c.size()) * std::numeric_limits<double>::epsilon() * 0.5;
    return n2u / (1.0 - n2u) * sum;
}

/// The polynomial as a DifferentiableFunction for refine_root, counting its
/// evaluations.
class PolynomialFunction {
public:
    explicit PolynomialFunction(std::span<const double> c) : c_(c) {}
    ValueAndDerivative operator()(double t) {
        ++evaluations_;
        return horner(c_, t);
    }
    [[nodiscard]] int evaluations() const { return evaluations_; }

private:
    std::span<const double> c_;
    int evaluations_ = 0;
};

/// The first root through a solver that writes roots in increasing order.
template <class Solver>
FirstPolynomialRoot first_root_with(Solver&& solve, std::span<const double> c, double t0, double t1) {
    std::array<double, 1> root{};
    const PolynomialRoots r = solve(c, t0, t1, std::span<double>(root));
    return {r.count > 0, r.count > 0 ? root[0] : std::numeric_limits<double>::quiet_NaN(), r.evaluations};
}

}  // namespace zeroset
